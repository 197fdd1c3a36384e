// SPDX-License-Identifier: Apache-2.0
// A solution written by another program (RenderPark, a script of one's own), read for
// `hmcr error` (docs/design.md §11.4, "What a foreign solution needs"): VTK XML PolyData of
// polygons with
//   point data  Radiosity  3 components (Float32 or Float64): the radiosity B at each point, W/m^2
//   cell data   PatchId    Int32 or Int64: the scene patch (face, in file order) of each polygon
//               Side       (optional) UInt8 or Int32: 0 the front, 1 the back of a two-sided patch
// Within a polygon the field is the barycentric interpolation of its points' values over its
// triangles, as an hmcr solution's (viz/cell_triangles.h). Nothing else is needed:
// each polygon's area and mean are computed, and no metadata is read.
#pragma once

#include <cstdint>
#include <filesystem>

#include "radiosity/shaded_mesh.h"

namespace hmcr {

// Throws InputError naming the file for a file that is missing, unreadable or inconsistent
// (a PatchId not below patch_count, a Side other than 0 and 1, a radiosity that is negative or
// not finite, a cell naming a point that is not there).
ShadedMesh read_foreign_solution(const std::filesystem::path& path, std::uint64_t patch_count);

}  // namespace hmcr
