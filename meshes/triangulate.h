// SPDX-License-Identifier: Apache-2.0
// Triangulation of one polygon (convex or concave, no holes except MGF-style seams) by ear
// clipping in its best-fit plane. Used by the repairs (meshes/repairs.h) for polygons of more
// than four corners, concave quads and non-planar quads.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace hmcr {

// Polygons with more corners are refused: the self-intersection test and ear clipping are
// quadratic in the corner count (10,000 corners: about 0.8 s, at most about 4 s, when ear
// clipping gives up: docs/usage.md#bad-input).
inline constexpr std::size_t kMaxPolygonCorners = 10'000;

// Why a polygon of more corners is refused: "polygon with N corners: at most 10000 are
// triangulated" (for every reader alike).
std::string too_many_corners(std::size_t corners);

// A plane through `origin` with orthonormal axes u, v and normal = u x v.
struct PolygonPlane {
    Eigen::Vector3d origin, u, v, normal;
};

// The least-squares plane of the corners (through their centroid, normal along the direction
// of least spread), its normal on the side of the polygon's Newell normal, so that the corners
// run counter-clockwise in (u, v) as they do seen from the front. Nothing when the Newell
// normal vanishes (a polygon with no area, or one that winds both ways like a figure eight).
std::optional<PolygonPlane> best_fit_plane(const std::vector<Eigen::Vector3d>& corners);

// Indices into the polygon's corners, counter-clockwise like the polygon.
using CornerTriangle = std::array<std::size_t, 3>;

struct Triangulation {
    std::vector<CornerTriangle> triangles;  // empty when error is set
    std::string error;                      // why the polygon has no safe triangulation
};

// Ear clipping in the best-fit plane. `ids` are the welded corner ids: equal ids are one point,
// so a seam (an edge walked there and back, MGF's way to cut a hole) is allowed, and so are
// zero-area corners (dropped). A polygon whose edges cross or touch elsewhere is an error.
// The triangles cover exactly the polygon's projected area (checked).
Triangulation triangulate(const std::vector<Eigen::Vector3d>& corners, const std::vector<int>& ids);

// The area of the polygon projected into its best-fit plane (0 without one).
double projected_area(const std::vector<Eigen::Vector3d>& corners);

}  // namespace hmcr
