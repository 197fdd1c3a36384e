// SPDX-License-Identifier: Apache-2.0
#include "viz/shaded_tracer.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "rays/embree_scene.h"
#include "tests/support/image_checks.h"

namespace hmcr {
namespace {

using test::kFloatTol;

TEST(EmbreeSoup, ReportsTriangleBarycentricsAndDistance) {
    // Triangle 0 at z = 0, triangle 1 (a reversed copy) at z = -1 behind it.
    const std::vector<Vec3> v = {{0, 0, 0},  {1, 0, 0},  {0, 1, 0},
                                 {0, 0, -1}, {0, 1, -1}, {1, 0, -1}};
    const EmbreeScene scene(v, {{0, 1, 2}, {3, 4, 5}});
    const auto hit = scene.first_hit_triangle(Vec3(0.25, 0.5, 2), Vec3(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->triangle, 0u);
    EXPECT_NEAR(hit->u, 0.25, kFloatTol);  // weight of vertex 1 = (1, 0, 0)
    EXPECT_NEAR(hit->v, 0.5, kFloatTol);   // weight of vertex 2 = (0, 1, 0)
    EXPECT_NEAR(hit->distance, 2, kFloatTol);
    // From between the two, upwards and downwards: both sides of a triangle are hit.
    const auto below = scene.first_hit_triangle(Vec3(0.25, 0.5, -0.5), Vec3(0, 0, -1));
    ASSERT_TRUE(below);
    EXPECT_EQ(below->triangle, 1u);
    EXPECT_NEAR(below->u, 0.5, kFloatTol);  // vertex 1 of triangle 1 is (0, 1, -1)
    EXPECT_NEAR(below->v, 0.25, kFloatTol);
    EXPECT_EQ(scene.first_hit(Vec3(0.25, 0.5, 2), Vec3(0, 0, -1))->patch, 0u);
    EXPECT_FALSE(scene.first_hit_triangle(Vec3(2, 2, 1), Vec3(0, 0, -1)));
}

TEST(EmbreeSoup, EmptyAndInvalidSoups) {
    const EmbreeScene empty(std::vector<Vec3>{}, {});
    EXPECT_FALSE(empty.first_hit_triangle(Vec3(0, 0, 1), Vec3(0, 0, -1)));
    EXPECT_THROW(EmbreeScene({Vec3(0, 0, 0)}, {{0, 0, 1}}), std::invalid_argument);
}

// A unit square as two cells: a triangle (0, 1, 3) and a pentagon-like polygon with a point in
// the middle of an edge, the shape conforming polygons have beside finer neighbours.
ShadedMesh square_with_t_vertex() {
    ShadedMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0.5, 0}};
    for (const Vec3& p : m.points)
        m.point_radiosity.push_back(Rgb(p.x(), p.y(), 1 + p.x() + p.y()));
    m.connectivity = {0, 1, 3, 1, 4, 2, 3};
    m.offsets = {0, 3, 7};
    m.patch_id = {0, 0};
    return m;
}

TEST(ShadedTracer, InterpolatesPointRadiosityFromEitherSide) {
    const ShadedTracer tracer(square_with_t_vertex());
    // The point radiosity is linear in position, so every triangle reproduces it exactly.
    for (const Vec3& p : {Vec3(0.2, 0.3, 0), Vec3(0.9, 0.6, 0), Vec3(0.6, 0.8, 0)}) {
        for (const double side : {1.0, -1.0}) {
            const auto hit = tracer.hit_along(p + Vec3(0, 0, side), Vec3(0, 0, -side));
            ASSERT_TRUE(hit);
            EXPECT_NEAR(hit->distance, 1, kFloatTol);
            EXPECT_TRUE(hit->radiosity.isApprox(Rgb(p.x(), p.y(), 1 + p.x() + p.y()), kFloatTol))
                << hit->radiosity.transpose();
        }
    }
    EXPECT_EQ(tracer.cell_along(Vec3(0.2, 0.3, 1), Vec3(0, 0, -1)), 0u);
    EXPECT_EQ(tracer.cell_along(Vec3(0.9, 0.6, 1), Vec3(0, 0, -1)), 1u);
    EXPECT_FALSE(tracer.radiosity_along(Vec3(0.2, 0.3, 1), Vec3(0, 0, 1)));
}

}  // namespace
}  // namespace hmcr
