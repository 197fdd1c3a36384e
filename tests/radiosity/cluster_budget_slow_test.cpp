// A budget of 5,000 leaves on a scene of 10^5 patches (docs/design.md §2.7): reached within
// the default tolerance with clusters as leaves, and the furnace it meshes keeps its power
// exactly. Slow: the budget search solves the 101,400-patch box a few times.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/budget_search.h"
#include "radiosity/solver.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

TEST(ClusterBudget, FiveThousandLeavesOnAHundredThousandPatches) {
    const double rho = 0.5, e = 1;
    const PatchMesh mesh = make_patch_mesh(
        inward_box({0, 0, 0}, {1, 1, 1}, 130, Rgb::Constant(rho), Rgb::Constant(e)));
    ASSERT_GT(mesh.n_faces(), 100'000u);
    SolverOptions o;
    o.clustering = Clustering::isotropic;
    o.rays = 1'000'000;
    o.seed = 2;
    const BudgetResult r = solve_for_budget(mesh, o, BudgetOptions{.leaves = 5'000});
    const SolveStats& st = r.solution.stats;
    EXPECT_LE(std::abs(double(st.leaves) - 5'000), 50.0) << st.leaves;
    EXPECT_GT(st.cluster_leaves, 0u);
    // Every ray in the closed box lands and deposits rho times its power, through cluster
    // leaves or not, so the area-weighted mean of B over the patches is the K-bounce value of
    // the frozen pass's K iterations exactly (up to the quanta's rounding).
    const std::size_t k = st.value_iterations().size();
    const double expected = e * (1 - std::pow(rho, double(k + 1))) / (1 - rho);
    double sum = 0, area = 0;
    const Hierarchy& h = *r.solution.hierarchy;
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        sum += h.root(p).area * h.root(p).radiosity[1];
        area += h.root(p).area;
    }
    EXPECT_NEAR(sum / area, expected, 1e-6 * expected);
}

}  // namespace
}  // namespace hmcr::test
