// SPDX-License-Identifier: Apache-2.0
// A solution's leaves as a discretisation: its cells reduced to their triangles and quads, and
// the information measures of that discretisation (docs/design.md §7).
#include "information/leaf_patches.h"

#include <gtest/gtest.h>

#include <array>

#include "information/scene_information.h"
#include "radiosity/oracle_registry.h"
#include "radiosity/shaded_mesh.h"
#include "radiosity/solver.h"
#include "tests/support/information.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

TEST(LeafPatches, CellsBecomeTheirLeavesWithTheSameArea) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1)));
    SolverOptions o;
    o.oracle = oracle_registry().find("power");
    o.epsilon = 1e-3;
    o.rays = 200'000;
    const Solution sol = solve(mesh, o);
    const ShadedMesh shaded = build_shaded_mesh(*sol.hierarchy);
    const PatchSet leaves = leaf_patches(shaded);
    ASSERT_EQ(leaves.patches.size(), sol.stats.leaves);
    std::size_t with_t_junctions = 0;
    for (std::size_t c = 0; c < shaded.cell_count(); ++c) {
        with_t_junctions += shaded.offsets[c + 1] - shaded.offsets[c] > 4;
        EXPECT_NEAR(leaves.patches[c].area, shaded.element_area[c], 1e-12) << c;
        EXPECT_EQ(leaves.patches[c].corner_count, 4);
    }
    EXPECT_GT(with_t_junctions, 0u);  // the reduction was needed
    EXPECT_NEAR(leaves.total_area, 6.0, 1e-9);

    // The continuous I^c_S does not depend on the discretisation; I_S grows with refinement and
    // stays below I^c_S, each up to the standard errors and the plug-in bias bound of I_S
    // (tests/support/information.h), which the leaves' ~2,000 rays each make large.
    const LineOptions lines{LineMethod::local, 2'000'000, 16, 1};
    const auto [coarse, coarse_bias, coarse_open] = measure_channel(build_patch_set(mesh), lines);
    const auto [fine, fine_bias, fine_open] = measure_channel(leaves, lines);
    EXPECT_TRUE(
        within_standard_errors("I^c_S leaves vs patches", fine.i_cs.estimate, coarse.i_cs.estimate,
                               std::hypot(fine.i_cs.standard_error, coarse.i_cs.standard_error)));
    EXPECT_GT(
        fine.i_s.estimate - fine_bias - kZ * (fine.i_s.standard_error + coarse.i_s.standard_error),
        coarse.i_s.estimate);
    EXPECT_LE(fine.i_s.estimate - kZ * fine.discretisation_error.standard_error,
              fine.i_cs.estimate + fine_bias);
}

// A higher-order solution's n x n sub-cells of a leaf are one patch, the leaf's own: the leaves
// of the same tree shaded on the constant basis, corner for corner.
TEST(LeafPatches, SubCellsOfALeafAreOnePatch) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1)));
    SolverOptions o;
    o.oracle = oracle_registry().find("power");
    o.epsilon = 1e-3;
    o.rays = 20'000;
    o.basis = Basis::quadratic;
    const Solution sol = solve(mesh, o);
    const ShadedMesh shaded = build_shaded_mesh(*sol.hierarchy);
    ASSERT_EQ(shaded.cell_count(), 9 * sol.stats.faces);
    const PatchSet leaves = leaf_patches(shaded);
    ASSERT_EQ(leaves.patches.size(), sol.stats.faces);
    ASSERT_EQ(leaf_first_cells(shaded).size(), sol.stats.faces);
    std::size_t l = 0;
    sol.hierarchy->for_each_leaf([&](const Element& e) {
        const std::array<Vec3, 4> corners = sol.hierarchy->corners(e);
        const Patch& p = leaves.patches[l++];
        ASSERT_EQ(p.corner_count, 4);
        for (int k = 0; k < 4; ++k) EXPECT_TRUE(p.corner[k].isApprox(corners[k], 1e-14));
        EXPECT_NEAR(p.area, e.area, 1e-12);
    });
    EXPECT_NEAR(leaves.total_area, 6.0, 1e-9);
}

}  // namespace
}  // namespace hmcr::test
