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
    // Every ray deposits rho times its power where it lands, through cluster leaves or not:
    // the patches' reflected power is rho times the frozen pass's shot power less what escaped
    // (through the box's edges, a few rays) and what backs absorbed, up to the quanta's
    // rounding.
    double reflected = 0;
    const Hierarchy& h = *r.solution.hierarchy;
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        reflected += h.root(p).area * (h.root(p).radiosity[1] - e);
    }
    const double landed = st.shot_power[1] - st.escaped_power[1] - st.back_face_power[1];
    EXPECT_NEAR(reflected, rho * landed, 1e-9 * rho * landed);
    EXPECT_LT(st.escaped_power[1], 1e-4 * st.shot_power[1]);  // a guard: the box is closed
}

}  // namespace
}  // namespace hmcr::test
