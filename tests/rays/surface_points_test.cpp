// SPDX-License-Identifier: Apache-2.0
// The point reference's quadrature points: stratified, jittered, on their patches, weighing
// each side's area, the same for any thread count.
#include "rays/surface_points.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <map>

#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

PatchSet patches_of(const std::vector<TestPolygon>& polygons) {
    return build_patch_set(make_patch_mesh(polygons));
}

// A square, a triangle and a quad that is no parallelogram, the square two-sided.
std::vector<TestPolygon> three_shapes() {
    TestPolygon square = axis_rectangle(2, 0, {0, 0}, {1, 1}, true);
    square.two_sided = true;
    TestPolygon triangle;
    triangle.corners = {Vec3(2, 0, 0), Vec3(4, 0, 0), Vec3(2, 1, 0)};
    TestPolygon kite;
    kite.corners = {Vec3(5, 0, 0), Vec3(7, 0, 0), Vec3(6.5, 1.5, 0), Vec3(5, 1, 0)};
    return {square, triangle, kite};
}

TEST(SurfacePoints, ASquareGetsItsTargetAsAGridAndWeighsItsArea) {
    const PatchSet set = patches_of({axis_rectangle(2, 0, {0, 0}, {2, 1}, true)});
    const std::vector<SurfacePoint> points = stratified_points(set, 5000);
    ASSERT_EQ(points.size(), 100u * 50u);  // 2 : 1, 5000 strata of 4e-4 m^2
    EXPECT_EQ(stratified_point_count(set, 5000), points.size());
    double weight = 0;
    for (const SurfacePoint& p : points) {
        weight += p.weight;
        EXPECT_DOUBLE_EQ(p.weight, 2.0 / 5000);
    }
    EXPECT_NEAR(weight, 2.0, 1e-12);
}

TEST(SurfacePoints, EveryStratumHoldsOnePointOnItsPatch) {
    const PatchSet set = patches_of({axis_rectangle(2, 0, {0, 0}, {1, 1}, true)});
    const std::vector<SurfacePoint> points = stratified_points(set, 400);
    ASSERT_EQ(points.size(), 400u);
    std::map<std::pair<int, int>, int> cells;
    for (const SurfacePoint& p : points) {
        EXPECT_EQ(p.patch, 0u);
        EXPECT_EQ(p.side, kFront);
        EXPECT_EQ(p.position.z(), 0);
        ++cells[{int(p.position.x() * 20), int(p.position.y() * 20)}];
    }
    EXPECT_EQ(cells.size(), 400u);  // one point in each of the 20 x 20 cells
}

// Per side, the weights sum to the side's area: exactly on triangles and parallelograms, and
// without bias on a quad that is not one, within 4 standard errors of the jitter (J is affine
// in (u, v) there, so a stratum's weight J(u, v) / n has variance (c1^2 du^2 + c2^2 dv^2) / (12
// n^2), c1 and c2 its slopes, computed here from the corners).
TEST(SurfacePoints, EachSidesWeightsSumToItsArea) {
    const PatchSet set = patches_of(three_shapes());
    const std::vector<SurfacePoint> points = stratified_points(set, 3000);
    std::map<std::pair<std::uint32_t, std::uint8_t>, double> area;
    for (const SurfacePoint& p : points) area[{p.patch, p.side}] += p.weight;
    ASSERT_EQ(area.size(), 4u);  // the square's two sides, the triangle, the kite
    const auto side = [&](std::uint32_t patch, std::uint8_t s) { return area[{patch, s}]; };
    EXPECT_NEAR(side(0, kFront), 1.0, 1e-12);
    EXPECT_NEAR(side(0, kBack), 1.0, 1e-12);
    EXPECT_NEAR(side(1, kFront), 1.0, 1e-12);
    const Patch& kite = set.patches[2];
    ASSERT_FALSE(kite.is_parallelogram());
    const SideStrata k = side_strata(kite, set.total_area / 3000);
    const double n = double(k.ku) * k.kv;
    const double c1 = kite.jacobian(Vec2(1, 0)) - kite.jacobian(Vec2(0, 0));
    const double c2 = kite.jacobian(Vec2(0, 1)) - kite.jacobian(Vec2(0, 0));
    const double variance = n * (c1 * c1 / (k.ku * k.ku) + c2 * c2 / (k.kv * k.kv)) / (12 * n * n);
    EXPECT_TRUE(within_standard_errors("the kite's weights", side(2, kFront), kite.area,
                                       std::sqrt(variance)));
}

TEST(SurfacePoints, PointsLieOnTheirPatchesInsideTheirDomains) {
    const PatchSet set = patches_of(three_shapes());
    for (const SurfacePoint& p : stratified_points(set, 2000)) {
        const Patch& patch = set.patches[p.patch];
        EXPECT_NEAR(patch.normal.dot(p.position - patch.corner[0]), 0, 1e-12);
        const Vec2 uv = patch.param(p.position);
        EXPECT_TRUE(patch.point(uv).isApprox(p.position, 1e-9)) << p.position.transpose();
        EXPECT_GT(p.weight, 0);
    }
}

TEST(SurfacePoints, ASmallSideIsOneStratumAndTheCountFollowsTheTarget) {
    const PatchSet set = patches_of({axis_rectangle(2, 0, {0, 0}, {1, 1}, true),
                                     axis_rectangle(2, 0, {2, 0}, {2.001, 0.001}, true)});
    const std::vector<SurfacePoint> points = stratified_points(set, 100);
    ASSERT_EQ(points.size(), 101u);
    EXPECT_EQ(points.back().patch, 1u);
    EXPECT_NEAR(points.back().weight, 1e-6, 1e-18);
}

TEST(SurfacePoints, AnotherStrataSeedJittersTheSameStrataAnew) {
    const PatchSet set = patches_of(three_shapes());
    const std::vector<SurfacePoint> a = stratified_points(set, 2000),
                                    b = stratified_points(set, 2000, 1);
    ASSERT_EQ(a.size(), b.size());
    std::size_t same = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        same += a[i].position == b[i].position;
        EXPECT_EQ(a[i].patch, b[i].patch);
        EXPECT_EQ(a[i].side, b[i].side);
    }
    EXPECT_EQ(same, 0u);
}

TEST(SurfacePoints, TheSameForAnyThreadCount) {
    const PatchSet set = patches_of(three_shapes());
    std::vector<SurfacePoint> one;
    tbb::task_arena single(1);
    single.execute([&] { one = stratified_points(set, 5000); });
    const std::vector<SurfacePoint> all = stratified_points(set, 5000);
    ASSERT_EQ(one.size(), all.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_TRUE(one[i].position == all[i].position);
        EXPECT_EQ(one[i].weight, all[i].weight);
    }
}

}  // namespace
}  // namespace hmcr::test
