// SPDX-License-Identifier: Apache-2.0
// Repairs of a polygon soup that have one safe meaning (docs/usage.md#repairs), made between a
// reader and the patch-mesh builder unless the load is strict.
#pragma once

#include "meshes/polygon_soup.h"
#include "meshes/repair_report.h"
#include "meshes/weld.h"

namespace hmcr {

// Repairs the soup in place: every polygon the builder would refuse for a RepairKind
// is replaced by what it means (its triangles, its distinct corners, a side of another face) or
// dropped. Throws
// InputError at the polygon's place when it has no safe meaning (a self-intersecting polygon).
// The soup's other content (positions, materials, places) is kept; new polygons keep the place
// of the one they replace.
RepairReport repair_soup(PolygonSoup& soup);
// The same with the soup's welding, weld(soup.positions), already made. The repairs keep the
// positions, so the welding stays valid for build_patch_mesh.
RepairReport repair_soup(PolygonSoup& soup, const Welding& welding);

// What a strict load repairs: two faces on the same vertices facing away from each other are one
// surface with two sides (meshes/coincident_faces.h).
RepairReport join_opposite_faces(PolygonSoup& soup, const Welding& welding);

}  // namespace hmcr
