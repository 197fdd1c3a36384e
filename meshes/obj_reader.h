// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ with its MTL material libraries, read by hmcr itself (docs/design.md §11.2).
#pragma once

#include <filesystem>

#include "meshes/polygon_soup.h"

namespace hmcr {

// The OBJ's polygons and materials. Throws InputError "path:line: why" on a file that cannot
// be read or a statement that is not valid OBJ/MTL; unknown MTL statements become warnings.
PolygonSoup read_obj(const std::filesystem::path& obj);

}  // namespace hmcr
