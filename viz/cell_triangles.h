// SPDX-License-Identifier: Apache-2.0
// The triangles of a ShadedMesh's polygons, without zero-area triangles: what the tracer gives
// Embree and what the object-space error integrates over (docs/design.md §6.4).
//
// A leaf polygon is convex, and beside finer neighbours it has points on its edges (the
// conforming polygons' T-vertices). A fan from its first point would join such a point to the
// apex by a triangle of zero area, and Embree never hits one: a ray through the neighbour's
// edge there would pass between the cells. Instead the polygon's triangles are clipped from it
// one by one, each with a real corner at its tip, so that every edge of the polygon is the edge
// of one triangle and neighbouring cells meet edge to edge. Where no point lies on a line
// through its two neighbours this is the fan from the first point, triangle by triangle.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "radiosity/shaded_mesh.h"

namespace hmcr {

// One triangle of a cell: indices into ShadedMesh::points, in the polygon's orientation, and
// the cell it came from.
struct CellTriangle {
    std::array<std::uint32_t, 3> points;
    std::uint32_t cell = 0;
};

// The triangles of every cell, in cell order (n - 2 for a polygon of n points). Throws
// std::invalid_argument when offsets or connectivity are malformed.
std::vector<CellTriangle> triangulate_cells(const ShadedMesh& mesh);

}  // namespace hmcr
