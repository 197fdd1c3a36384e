// A solution's leaves as a discretisation: its cells reduced to their triangles and quads, and
// the information measures of that discretisation (SPEC section 7).
#include "studies/leaf_patches.h"

#include <gtest/gtest.h>

#include "radiosity/solver.h"
#include "studies/scene_information.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"
#include "viz/shaded_mesh.h"

namespace hmcr::test {
namespace {

TEST(LeafPatches, CellsBecomeTheirLeavesWithTheSameArea) {
    const PatchMesh mesh = make_patch_mesh(
        inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1)));
    SolverOptions o;
    o.oracle = "power";
    o.epsilon = 1e-3;
    o.rays = 200'000;
    const Solution sol = solve(mesh, o);
    const ShadedMesh shaded = build_shaded_mesh(*sol.hierarchy, mesh);
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
    // stays below I^c_S. The plug-in I_S is biased upward by few lines per leaf (at 2 M lines,
    // about 2,000 per leaf, it read 1.67 > I^c_S = 1.61), so 10 M lines (0.11 bits below).
    LineOptions lines;
    lines.lines = 10'000'000;
    const InformationMeasures coarse = scene_information(build_patch_set(mesh), lines);
    const InformationMeasures fine = scene_information(leaves, lines);
    EXPECT_TRUE(within_standard_errors(
        "I^c_S leaves vs patches", fine.i_cs.estimate, coarse.i_cs.estimate,
        std::hypot(fine.i_cs.standard_error, coarse.i_cs.standard_error)));
    EXPECT_GT(fine.i_s.estimate, coarse.i_s.estimate + 1);
    EXPECT_LT(fine.i_s.estimate, fine.i_cs.estimate);
}

}  // namespace
}  // namespace hmcr::test
