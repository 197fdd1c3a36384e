// SPDX-License-Identifier: Apache-2.0
// Reading a solution back from its .vtp (docs/design.md §5) for rendering and comparison.
#pragma once

#include <filesystem>

#include "radiosity/shaded_mesh.h"
#include "viz/vtk_export.h"
#include "viz/vtp_io.h"

namespace hmcr {

// The ShadedMesh an hmcr .vtp holds, and its metadata if asked. Every array's type, component
// count and length, every cell and every value is checked: throws InputError naming the file
// for a file that is missing, unreadable, not made by this version of hmcr, or inconsistent
// (a PatchId out of range, a negative or NaN radiosity, a cell naming a point that is not there).
ShadedMesh read_vtp(const std::filesystem::path& path, VtpMetadata* metadata = nullptr);

// The polygons of `data` into m.offsets and m.connectivity, each checked to have 3 points or
// more, all of them in the file (the part of read_vtp a foreign solution shares).
void read_polygon_cells(vtkPolyData* data, const VtpChecker& check, ShadedMesh& m);

}  // namespace hmcr
