// SPDX-License-Identifier: Apache-2.0
// View importance (docs/design.md §3.12): the views' pixel shares, the adjoint solve's exact
// total in a closed box, and elements where the views look.
#include "radiosity/view_importance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radiosity/solver.h"
#include "rays/embree_scene.h"
#include "tests/support/furnace.h"
#include "tests/support/plugins.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// A view from 1 m in front of the plate z = 0 (x, y in [-5, 5], facing +z) at its centre.
View view_of_plate(double z) { return test_view({0, 0, z}, {0, 0, 0}, 40, 16); }

std::vector<double> shares_of(const std::vector<TestPolygon>& polygons, const View& view) {
    const PatchSet ps = build_patch_set(make_patch_mesh(polygons));
    const EmbreeScene scene(ps);
    return view_pixel_shares(ps, scene, std::vector<View>{view});
}

TEST(ViewImportance, APlateThatFillsTheViewHasEveryPixel) {
    TestPolygon plate = axis_rectangle(2, 0, {-5, -5}, {5, 5}, true);
    plate.reflectance = Rgb::Constant(0.5);
    EXPECT_EQ(shares_of({plate}, view_of_plate(1)), (std::vector<double>{1, 0}));
    // From behind: a one-sided plate's back is no side; a two-sided plate's back has them all.
    EXPECT_EQ(shares_of({plate}, view_of_plate(-1)), (std::vector<double>{0, 0}));
    plate.two_sided = true;
    EXPECT_EQ(shares_of({plate}, view_of_plate(-1)), (std::vector<double>{0, 1}));
}

// Two plates meeting under the view's centre line: an even image has half its pixels on each.
TEST(ViewImportance, TwoPlatesShareTheViewInHalves) {
    TestPolygon left = axis_rectangle(2, 0, {-5, -5}, {0, 5}, true);
    TestPolygon right = axis_rectangle(2, 0, {0, -5}, {5, 5}, true);
    EXPECT_EQ(shares_of({left, right}, view_of_plate(1)), (std::vector<double>{0.5, 0, 0.5, 0}));
}

// Inside a closed box of reflectance rho every ray lands, so the importance solve's total is
// exact: after K iterations, each adding a bounce, sum A K = rho (1 + rho + ... + rho^K) for
// pixel shares summing to 1, so sum A I = (1 - rho^(K+1)) / (1 - rho), whatever the view sees.
TEST(ViewImportance, TheAdjointTotalIsExactInAClosedBox) {
    const double rho = 0.6;
    const PatchSet ps = build_patch_set(
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(rho), Rgb::Zero())));
    const EmbreeScene scene(ps);
    SolverOptions o;
    o.rays = 50'000;
    const std::vector<View> views{test_view({0.5, 0.5, 0.5}, {0.1, 0.2, 0.0}, 60, 24)};
    const ViewImportance vi = solve_view_importance(ps, scene, views, o, o.rays);
    double total = 0;
    for (std::size_t p = 0; p < ps.patches.size(); ++p) {
        total += ps.patches[p].area * vi.importance[2 * p][1];
    }
    const double expected = furnace_value(rho, 1, vi.iterations);
    EXPECT_NEAR(total, expected, 1e-9 * expected);
    EXPECT_GT(vi.iterations, 3u);
}

// A view of the floor's left half from close above: with importance the left half gets more
// of the elements than the right; without, the two halves are alike.
TEST(ViewImportance, ElementsGoWhereTheViewLooks) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 4, Rgb::Constant(0.3), Rgb::Constant(1)));
    SolverOptions o;
    o.oracle = test::oracle("power");
    o.rays = 200'000;
    o.epsilon = 2e-5;
    o.refine_share = 1;
    const std::vector<View> views{test_view({0.25, 0.8, 0.5}, {0.25, 0, 0.5}, 30, 64)};
    auto floor_halves = [&](Importance importance) {
        o.importance = importance;
        const Solution sol = solve(mesh, o, {views});
        const PatchSet& ps = sol.hierarchy->patch_set();
        std::array<double, 2> leaves{0, 0};  // left (x < 0.5), right
        sol.hierarchy->for_each_leaf([&](const Element& e) {
            const Patch& p = ps.patches[e.id.patch];
            const Vec3 c = (p.corner[0] + p.corner[1] + p.corner[2] + p.corner[3]) / 4;
            if (std::abs(c.y()) < 1e-9) leaves[c.x() < 0.5 ? 0 : 1] += 1;
        });
        return leaves;
    };
    const auto with = floor_halves(Importance::views), without = floor_halves(Importance::none);
    EXPECT_GT(with[0], 2 * with[1]) << with[0] << " left, " << with[1] << " right";
    EXPECT_LT(without[0], 1.5 * without[1]) << without[0] << " left, " << without[1] << " right";
}

// The scene's views must see something that reflects.
TEST(ViewImportance, ViewsThatSeeNothingAreAnInputError) {
    TestPolygon plate = axis_rectangle(2, 0, {-5, -5}, {5, 5}, true);
    plate.reflectance = Rgb::Constant(0.5);
    const PatchSet ps = build_patch_set(make_patch_mesh({plate}));
    const EmbreeScene scene(ps);
    const std::vector<View> away{test_view({0, 0, 1}, {0, 0, 2}, 40, 8)};
    EXPECT_THROW(solve_view_importance(ps, scene, away, SolverOptions{}, 1000), InputError);
}

}  // namespace
}  // namespace hmcr::test
