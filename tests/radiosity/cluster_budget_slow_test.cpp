// SPDX-License-Identifier: Apache-2.0
// Clusters on scenes of 10^4 and 10^5 patches (docs/design.md §2.7): a budget of 5,000 leaves
// on 101,400 patches reached with cluster leaves, the power it meshes kept exactly; a furnace of
// 10,086 patches on cluster leaves exact on every patch. Slow: many patches, many solves.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/budget_search.h"
#include "radiosity/solver.h"
#include "tests/support/furnace.h"
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

// A furnace of 6 x 41 x 41 = 10,086 patches meshed with cluster leaves (at epsilon 30 nearly all
// of its leaves are clusters) and frozen: every patch's B is the exact K-bounce value, t-tested
// over 10 seeds with Bonferroni over the patches.
TEST(ClusterBudget, FurnaceOfTenThousandPatchesIsExactOnEveryPatch) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 41, Rgb::Constant(0.5), Rgb::Constant(1)));
    expect_furnace_per_patch(
        mesh, 0.5, 1, 10,
        [](std::uint64_t seed) {
            SolverOptions o;
            o.clustering = Clustering::isotropic;
            o.rays = 400'000;
            o.seed = seed;
            o.epsilon = 30;
            return o;
        },
        [](const Solution& sol) {
            EXPECT_GT(2 * sol.stats.cluster_leaves, sol.stats.leaves) << sol.options.seed;
        });
}

}  // namespace
}  // namespace hmcr::test
