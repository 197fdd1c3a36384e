// SPDX-License-Identifier: Apache-2.0
#include "viz/cell_triangles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace hmcr {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// One cell, the polygon of `corners` in order, in the plane z = 0.
ShadedMesh one_cell(const std::vector<Vec3>& corners) {
    ShadedMesh m;
    m.points = corners;
    m.point_radiosity.assign(corners.size(), Rgb::Zero());
    for (std::size_t i = 0; i < corners.size(); ++i) m.connectivity.push_back(std::int64_t(i));
    m.offsets = {0, std::int64_t(corners.size())};
    m.patch_id = {0};
    return m;
}

double polygon_area(const std::vector<Vec3>& p) {
    Vec3 twice = Vec3::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) twice += p[i].cross(p[(i + 1) % p.size()]);
    return 0.5 * twice.norm();
}

// What a cell's triangles must be: n - 2 of them, none of zero area, oriented as the polygon,
// covering its area, and each edge between consecutive points the edge of exactly one triangle
// (so the cell beside it, which has the same points there, meets it edge to edge).
void expect_edge_to_edge(const std::vector<Vec3>& corners) {
    const ShadedMesh m = one_cell(corners);
    const std::vector<CellTriangle> t = triangulate_cells(m);
    ASSERT_EQ(t.size(), corners.size() - 2);
    const Vec3 up(0, 0, 1);
    double area = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const CellTriangle& tri : t) {
        EXPECT_EQ(tri.cell, 0u);
        const Vec3 &a = m.points[tri.points[0]], &b = m.points[tri.points[1]],
                   &c = m.points[tri.points[2]];
        const double twice = (b - a).cross(c - a).dot(up);
        EXPECT_GT(twice, 1e-3 * polygon_area(corners)) << "a triangle of (almost) zero area";
        area += twice / 2;
        for (int k = 0; k < 3; ++k) edges.emplace_back(tri.points[k], tri.points[(k + 1) % 3]);
    }
    EXPECT_NEAR(area, polygon_area(corners), 1e-12);
    for (std::uint32_t i = 0; i < corners.size(); ++i) {
        const auto edge = std::pair(i, std::uint32_t((i + 1) % corners.size()));
        EXPECT_EQ(std::count(edges.begin(), edges.end(), edge), 1)
            << "edge " << edge.first << "-" << edge.second;
    }
}

TEST(CellTriangles, APolygonOfCornersIsTheFanFromItsFirstPoint) {
    const ShadedMesh m = one_cell({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {2, 2, 0}, {0, 2, 0}});
    const std::vector<CellTriangle> t = triangulate_cells(m);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].points, (Triangle{0, 1, 2}));
    EXPECT_EQ(t[1].points, (Triangle{0, 2, 3}));
    EXPECT_EQ(t[2].points, (Triangle{0, 3, 4}));
}

TEST(CellTriangles, APointOnAnEdgeBesideTheFirstIsTheEdgeOfARealTriangle) {
    // The fan from (0, 0) would join it to (0, 0.5) on the left edge by a triangle of zero area.
    expect_edge_to_edge({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0.5, 0}});
    expect_edge_to_edge({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
}

TEST(CellTriangles, PointsOnEveryEdgeLeaveNoZeroAreaTriangle) {
    // Two points on each edge: no point of this square sees all the others across a real
    // triangle, so no fan would do.
    std::vector<Vec3> square;
    const Vec3 corners[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (int k = 0; k < 4; ++k) {
        const Vec3 &a = corners[k], &b = corners[(k + 1) % 4];
        for (const double s : {0.0, 0.25, 0.5}) square.push_back(a + s * (b - a));
    }
    expect_edge_to_edge(square);
    // A triangle with seven points on one edge and one on another.
    std::vector<Vec3> triangle = {{0, 0, 0}};
    for (int i = 1; i <= 8; ++i) triangle.push_back({i / 8.0, 0, 0});
    triangle.push_back({0.5, 0.5, 0});
    triangle.push_back({0, 1, 0});
    expect_edge_to_edge(triangle);
}

TEST(CellTriangles, EdgesOnACoordinateAxisInSinglePrecision) {
    // The case that passed rays between cells: a leaf of the wall x = 0 with a point on its
    // edge along the room's corner line, where every point has x = z = 0 exactly.
    std::vector<Vec3> leaf = {{0, 0.331567, 0},
                              {0.0115833, 0.331567, 0},
                              {0.0115833, 0.343, 0},
                              {0, 0.343, 0},
                              {0, 0.337283, 0}};
    expect_edge_to_edge(leaf);
}

TEST(CellTriangles, RefusesMalformedCells) {
    ShadedMesh bad = one_cell({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    bad.connectivity.back() = 9;
    EXPECT_THROW(triangulate_cells(bad), std::invalid_argument);
    ShadedMesh two = one_cell({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    two.offsets = {0, 2};
    EXPECT_THROW(triangulate_cells(two), std::invalid_argument);
    ShadedMesh offsets = one_cell({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    offsets.offsets = {1, 3};
    EXPECT_THROW(triangulate_cells(offsets), std::invalid_argument);
}

}  // namespace
}  // namespace hmcr
