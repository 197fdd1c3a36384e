// Budget search (docs/design.md §6): epsilon by bisection on log epsilon until the leaf count is
// within the tolerance, for every oracle; clean failures when the budget cannot be reached.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/error.h"
#include "meshes/scene.h"
#include "oracles/registry.h"
#include "radiosity/budget_search.h"

namespace hmcr::test {
namespace {

class BudgetForEveryOracle : public testing::TestWithParam<const Oracle*> {};

// A reported jump must be real: two epsilons a hair apart (the search stops at a log gap of
// 1e-6) whose leaf counts straddle the whole tolerance around the target.
void expect_genuine_jump(const std::string& why, std::size_t target) {
    ASSERT_NE(why.find("jumps from"), std::string::npos) << why;
    std::size_t above = 0, below = 0;
    double eps_above = 0, eps_below = 0;
    ASSERT_EQ(std::sscanf(why.c_str() + why.find("jumps from"),
                          "jumps from %zu to %zu between epsilon %lf and %lf", &above, &below,
                          &eps_above, &eps_below),
              4)
        << why;
    EXPECT_GT(above, target + target / 100) << why;
    EXPECT_LT(below, target - target / 100) << why;
    EXPECT_LT(std::log(eps_below / eps_above), 2e-6) << why;
    EXPECT_GT(eps_below, eps_above) << why;
}

// The leaf count is a step function of epsilon, and for some oracles and seeds one step jumps
// across the whole +-1% (vt at 2.68 M rays, seed 1: 1,095 leaves up to epsilon 9.47e-4, 960
// from 9.48e-4; at 300,000 rays ks and vt jump with seed 1). The search must then say so,
// naming a genuine jump, and another seed must reach the budget, with the probes consistent.
TEST_P(BudgetForEveryOracle, ReachesAThousandLeavesOnTheCornellBoxWithinOnePercent) {
    const Scene scene = load_scene("cornell");
    SolverOptions o;
    o.oracle = GetParam();
    o.rays = 300'000;
    for (o.seed = 1; o.seed <= 4; ++o.seed) {
        BudgetResult r;
        try {
            r = solve_for_budget(scene.mesh, o, {1000, 0.01});
        } catch (const BudgetNotReached& e) {
            expect_genuine_jump(e.what(), 1000);
            continue;
        }
        EXPECT_NEAR(double(r.solution.stats.leaves), 1000.0, 10.0);
        ASSERT_FALSE(r.probes.empty());
        EXPECT_EQ(r.probes.back().leaves, r.solution.stats.leaves);
        EXPECT_EQ(r.probes.back().epsilon, r.solution.stats.epsilon);
        EXPECT_LE(r.probes.size(), 15u);
        return;
    }
    ADD_FAILURE() << "no seed of 1-4 reached 1,000 +- 1% leaves";
}

INSTANTIATE_TEST_SUITE_P(Registry, BudgetForEveryOracle, testing::ValuesIn(oracle_registry().all()),
                         [](const testing::TestParamInfo<const Oracle*>& p) {
                             return std::string(p.param->name());
                         });

std::string failure(const SolverOptions& o, std::size_t leaves) {
    try {
        solve_for_budget(load_scene("cornell").mesh, o, {leaves, 0.01});
    } catch (const BudgetNotReached& e) {
        return e.what();
    }
    return "no failure";
}

TEST(BudgetSearch, FailsCleanlyWhenTheLimitsCapTheLeafCount) {
    SolverOptions o;
    o.rays = 50'000;
    o.max_depth = 2;  // at most 24 * 16 = 384 leaves
    const std::string why = failure(o, 5000);
    EXPECT_NE(why.find("budget of 5000 leaves"), std::string::npos) << why;
    EXPECT_NE(why.find("max-depth 2"), std::string::npos) << why;
}

TEST(BudgetSearch, FailsCleanlyBelowThePatchCount) {
    const std::string why = failure(SolverOptions{}, 10);
    EXPECT_NE(why.find("24 patches"), std::string::npos) << why;
}

}  // namespace
}  // namespace hmcr::test
