// SPDX-License-Identifier: Apache-2.0
// Faces on the same vertices (docs/design.md §1.6): a copy is dropped, two faces facing away
// from each other are one surface with two sides, and a copy in another material loses to the
// first. Part of the repairs (meshes/repairs.h); the joining of opposite faces is also made by a
// strict load, for it is how MGF and modellers write a thin surface with two materials.
#pragma once

#include <vector>

#include "meshes/polygon_soup.h"
#include "meshes/repair_report.h"

namespace hmcr {

// On the repaired soup (triangles and quads), with `welded` the welding's ids of its positions:
// of the faces on one set of vertices, in file order,
// - a face with the same corners in the same cyclic order, the same material and the same back
//   as an earlier one is dropped (duplicate_dropped; materials equal in value count as one);
// - a face facing the other way becomes the back of the first: its material is the back's
//   (sides_joined), whatever backs either face had (each side is the material of the face
//   that faces that way);
// - a face facing the same way in another material (or back) is dropped, the first kept
//   (coincident_dropped).
// A third face left after those rules is an error at its place naming the other two: a surface
// has two sides. Dropped faces are counted in `report` at their places; the kept ones stay in
// order.
void resolve_coincident_faces(PolygonSoup& soup, const std::vector<int>& welded,
                              RepairReport& report);

// The same rules on the faces of 5 corners or more, before the repairs cut them into triangles
// (with their repeated and collinear corners out): two such faces facing away from each other
// would each be cut its own way, their triangles overlapping without one matching, so they are
// compared as polygons. A face with a corner twice is left as it is.
void resolve_coincident_polygons(PolygonSoup& soup, const std::vector<int>& welded,
                                 RepairReport& report);

// A strict load's part of that: exactly two faces on the same vertices, facing away from each
// other, are joined (sides_joined). Anything else is left for the builder to refuse.
void join_opposite_faces(PolygonSoup& soup, const std::vector<int>& welded, RepairReport& report);

}  // namespace hmcr
