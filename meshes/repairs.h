// Repairs of a polygon soup that have one safe meaning (README: Repairs), made between a reader
// and the patch-mesh builder unless the load is strict.
#pragma once

#include "meshes/polygon_soup.h"
#include "meshes/repair_report.h"

namespace hmcr {

// Repairs the soup in place: every polygon the builder would refuse for a RepairKind
// is replaced by what it means (its triangles, its distinct corners) or dropped. Throws
// InputError at the polygon's place when it has no safe meaning (a self-intersecting polygon).
// The soup's other content (positions, materials, places) is kept; new polygons keep the place
// of the one they replace.
RepairReport repair_soup(PolygonSoup& soup);

}  // namespace hmcr
