// Budget search (SPEC section 6): epsilon by bisection on log epsilon until the leaf count is
// within the tolerance, for every oracle; clean failures when the budget cannot be reached.
#include <gtest/gtest.h>

#include <cstdio>

#include "meshes/scene.h"
#include "oracles/registry.h"
#include "radiosity/budget_search.h"

namespace hmcr::test {
namespace {

class BudgetForEveryOracle : public testing::TestWithParam<const Oracle*> {};

// The leaf count is a step function of epsilon, and for some oracles and seeds one step jumps
// across the whole +-1% (vt at 2.68 M rays, seed 1: 1,095 leaves up to epsilon 9.47e-4, 960
// from 9.48e-4). The search must then say so, naming the jump; otherwise it must reach the
// budget. Either way the claim is checked: a reported jump straddles the target.
TEST_P(BudgetForEveryOracle, ReachesAThousandLeavesOnTheCornellBoxWithinOnePercent) {
    const Scene scene = load_scene("cornell");
    SolverOptions o;
    o.oracle = std::string(GetParam()->name());
    o.rays = 300'000;
    BudgetResult r;
    try {
        r = solve_for_budget(scene.mesh, o, {1000, 0.01});
    } catch (const std::invalid_argument& e) {
        const std::string why = e.what();
        ASSERT_NE(why.find("jumps from"), std::string::npos) << why;
        std::size_t above = 0, below = 0;
        ASSERT_EQ(std::sscanf(why.c_str() + why.find("jumps from"), "jumps from %zu to %zu",
                              &above, &below), 2) << why;
        EXPECT_GT(above, 1010u);
        EXPECT_LT(below, 990u);
        return;
    }
    EXPECT_NEAR(double(r.solution.stats.leaves), 1000.0, 10.0);
    ASSERT_FALSE(r.probes.empty());
    EXPECT_EQ(r.probes.back().leaves, r.solution.stats.leaves);
    EXPECT_EQ(r.probes.back().epsilon, r.solution.stats.epsilon);
    EXPECT_LE(r.probes.size(), 15u);
}

INSTANTIATE_TEST_SUITE_P(Registry, BudgetForEveryOracle, testing::ValuesIn(all_oracles()),
                         [](const testing::TestParamInfo<const Oracle*>& p) {
                             return std::string(p.param->name());
                         });

std::string failure(const SolverOptions& o, std::size_t leaves) {
    try {
        solve_for_budget(load_scene("cornell").mesh, o, {leaves, 0.01});
    } catch (const std::invalid_argument& e) {
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
