// SPDX-License-Identifier: Apache-2.0
// What `hmcr info --bounds` prints and the view a scene without views gets
// (meshes/scene_bounds.h): the up axis from the emitters, a view inside a closed room whichever
// axis is up, and from outside where there is no room.
#include "meshes/scene_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/support/test_scenes.h"

namespace hmcr {
namespace {

// A closed room of 3 x 3 grey quads a wall, inward, whose ceiling's middle quad is a light:
// the ceiling is the side of the box at hi[up], up being 0, 1 or 2.
PatchMesh lit_room_with_up(const Vec3& lo, const Vec3& hi, int up) {
    std::vector<test::TestPolygon> walls =
        test::inward_box(lo, hi, 3, Rgb::Constant(0.6), Rgb::Zero());
    for (test::TestPolygon& w : walls) {
        Vec3 centre = Vec3::Zero();
        for (const Vec3& p : w.corners) centre += p / double(w.corners.size());
        const Vec3 off = (centre - (lo + hi) / 2).cwiseQuotient(hi - lo);
        bool middle = centre[up] == hi[up];
        for (int a = 0; a < 3; ++a) middle = middle && (a == up || std::abs(off[a]) < 0.1);
        if (middle) w.emission = Rgb::Constant(10);
    }
    return test::make_patch_mesh(walls);
}

bool strictly_inside(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.array() > lo.array()).all() && (p.array() < hi.array()).all();
}

TEST(SceneBounds, BoxPatchesEmittersAndTheUpAxisOfTheLights) {
    const Vec3 lo(-1, 0, 0.5), hi(3, 3, 3);
    for (int up = 0; up < 3; ++up) {
        SCOPED_TRACE(up);
        const SceneBounds b = scene_bounds(lit_room_with_up(lo, hi, up));
        EXPECT_EQ(b.lo, lo);
        EXPECT_EQ(b.hi, hi);
        EXPECT_EQ(b.patches, 54u);
        EXPECT_EQ(b.two_sided, 0u);
        EXPECT_EQ(b.emitters, 1u);
        const double area = (hi - lo).prod() / (hi[up] - lo[up]) / 9;
        EXPECT_NEAR(b.emitting_area, area, 1e-12);
        EXPECT_NEAR(b.emitted_power.x(), 10 * area, 1e-10);
        EXPECT_EQ(b.up, Vec3::Unit(up));
        EXPECT_EQ(b.up_reason,
                  std::string("the emitters' centre is at 100% of the box along ") + "xyz"[up]);
    }
}

TEST(SceneBounds, WithoutEmittersUpIsObjsPlusY) {
    const SceneBounds b = scene_bounds(test::make_patch_mesh(
        test::inward_box({0, 0, 0}, {1, 2, 1}, 1, Rgb::Constant(0.5), Rgb::Zero())));
    EXPECT_EQ(b.up, Vec3(0, 1, 0));
    EXPECT_EQ(b.up_reason, "no emitters: OBJ's convention");
    EXPECT_EQ(b.emitters, 0u);
}

// A closed room is seen from inside, level, with its up axis up: whichever axis that is.
TEST(DefaultView, AClosedRoomIsSeenFromInsideWithItsUpAxisUp) {
    const Vec3 lo(0, 0, 0), hi(4, 3, 2.5);
    for (int up = 0; up < 3; ++up) {
        SCOPED_TRACE(up);
        const PatchMesh room = lit_room_with_up(lo, hi, up);
        const DefaultView v = default_view(room, scene_bounds(room));
        EXPECT_TRUE(v.inside);
        EXPECT_EQ(v.view.name, "default");
        EXPECT_TRUE(strictly_inside(v.view.position, lo, hi)) << v.view.position.transpose();
        EXPECT_EQ(v.view.up, Vec3::Unit(up));
        EXPECT_EQ(v.view.look_at[up], v.view.position[up]);  // level
        EXPECT_EQ(v.view.fov_degrees, 60);
    }
}

// A box facing out (an object, not a room) is seen from outside, from +z first.
TEST(DefaultView, AnObjectIsSeenFromOutside) {
    std::vector<test::TestPolygon> faces =
        test::inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1));
    for (test::TestPolygon& f : faces) std::reverse(f.corners.begin(), f.corners.end());
    const PatchMesh box = test::make_patch_mesh(faces);
    const DefaultView v = default_view(box, scene_bounds(box));
    EXPECT_FALSE(v.inside);
    EXPECT_EQ(v.view.look_at, Vec3(0.5, 0.5, 0.5));
    EXPECT_GT(v.view.position.z(), 1);
    EXPECT_EQ(v.view.position.head<2>(), v.view.look_at.head<2>());
    EXPECT_EQ(v.view.fov_degrees, 40);
}

}  // namespace
}  // namespace hmcr
