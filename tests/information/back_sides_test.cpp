// SPDX-License-Identifier: Apache-2.0
// Information measures by side (docs/design.md §7.7): a two-sided patch is two states, its front
// and its back, each with its own row of form factors, for a scene's patches and for a
// solution's leaves.
#include "information/back_sides.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "information/scene_information.h"
#include "radiosity/solver.h"
#include "tests/support/information.h"
#include "tests/support/plugins.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test::back_sides {
namespace {

// Two unit cubes side by side, [0, 1]^3 and [1, 2] x [0, 1]^2, their common face one two-sided
// square (its front in the first cube, its back in the second): two closed empty cubes, so each
// of the 12 states (5 + 5 walls, the two sides) has the empty cube's row, and a_i = 1/12.
std::vector<TestPolygon> two_rooms(const Rgb& emission) {
    std::vector<TestPolygon> scene;
    for (const double x0 : {0.0, 1.0}) {
        for (const TestPolygon& wall :
             inward_box({x0, 0, 0}, {x0 + 1, 1, 1}, 1, Rgb::Constant(0.5), emission)) {
            bool on_partition = true;
            for (const Vec3& c : wall.corners) on_partition &= c.x() == 1;
            if (!on_partition) scene.push_back(wall);
        }
    }
    TestPolygon partition = axis_rectangle(0, 1, {0, 0}, {1, 1}, false);
    partition.reflectance = partition.back_reflectance = Rgb::Constant(0.5);
    partition.emission = partition.back_emission = emission;
    partition.two_sided = true;
    scene.push_back(partition);
    return scene;
}

// The measures of the two rooms against the exact channel: H_P = log2 12, H_S the empty cube's,
// I_S = H_P - H_S (closed), within z standard errors and Paninski's bound for rows of 5 states
// and N / 12 rays each.
void expect_two_rooms(const InformationMeasures& m, std::uint64_t lines) {
    const EmptyCube cube = empty_cube();
    const double bias = std::log2(1 + 4 * 12.0 / double(lines));
    // Every ray lands on a side, but for the few that slip through Embree's float cracks along
    // the edges (a twelfth of them would meet the partition from behind and land on none if its
    // back were no state).
    EXPECT_LT(double(m.samples_open), 1e-4 * double(m.samples));
    EXPECT_EQ(m.patches_unsampled, 0u);
    EXPECT_NEAR(m.h_p.estimate, std::log2(12.0), 1e-12);
    EXPECT_TRUE(
        within_standard_errors("H_S", m.h_s.estimate, cube.h_s, m.h_s.standard_error, bias));
    EXPECT_TRUE(within_standard_errors("I_S", m.i_s.estimate, std::log2(12.0) - cube.h_s,
                                       m.i_s.standard_error, bias));
}

TEST(BackSides, APatchesTwoSidesAreTwoStatesOfTheChannel) {
    const PatchSet set = build_patch_set(make_patch_mesh(two_rooms(Rgb::Zero())));
    const ChannelStates c = patch_states(set);
    ASSERT_EQ(c.fronts(), 11u);
    ASSERT_EQ(c.states.patches.size(), 12u);
    EXPECT_NEAR(c.states.total_area, 12.0, 1e-12);
    EXPECT_TRUE(c.states.patches[11].normal.isApprox(Vec3(1, 0, 0)));  // out of the back
    for (const LineMethod method : {LineMethod::local, LineMethod::global}) {
        SCOPED_TRACE(line_method_name(method));
        const std::uint64_t lines = 1'200'000;
        expect_two_rooms(scene_information(set, {method, lines, 16, 3}), lines);
    }
}

// The same rooms solved (every side emits, so the partition's back has leaves): the solution's
// front and back leaves are the states, and the channel is still the two closed cubes'.
TEST(BackSides, ASolutionsBackLeavesAreStatesOfTheirOwn) {
    const PatchMesh mesh = make_patch_mesh(two_rooms(Rgb::Constant(1)));
    SolverOptions o;
    o.oracle = test::oracle("power");
    o.epsilon = 1e-3;
    o.rays = 100'000;
    const Solution sol = solve(mesh, o);
    const ShadedMesh shaded = build_shaded_mesh(*sol.hierarchy);
    const ChannelStates c = leaf_states(shaded);
    ASSERT_TRUE(c.backs);
    ASSERT_EQ(c.states.patches.size(), sol.stats.leaves);
    double back_area = 0;
    for (std::size_t s = c.fronts(); s < c.states.patches.size(); ++s) {
        back_area += c.states.patches[s].area;
        EXPECT_TRUE(c.states.patches[s].normal.isApprox(Vec3(1, 0, 0))) << s;
    }
    EXPECT_GT(c.states.patches.size() - c.fronts(), 1u);  // the back refined
    EXPECT_NEAR(back_area, 1.0, 1e-9);
    EXPECT_NEAR(c.states.total_area, 12.0, 1e-9);
    for (const LineMethod method : {LineMethod::local, LineMethod::global}) {
        const InformationMeasures m = scene_information(c, {method, 200'000, 16, 5});
        EXPECT_LT(double(m.samples_open), 1e-4 * double(m.samples)) << line_method_name(method);
    }
}

}  // namespace
}  // namespace hmcr::test::back_sides
