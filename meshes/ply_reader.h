// SPDX-License-Identifier: Apache-2.0
// PLY, the Stanford polygon file format (ascii, binary little and big endian), read by hmcr
// itself (docs/design.md §11.11). Read: the element `vertex` with x, y, z and the element `face`
// with its list `vertex_indices` (or `vertex_index`); a face's reflectance from its own `red`,
// `green`, `blue` (uchar 0-255, or float or double 0-1), else the mean of its corners' vertex
// colours; its emitted radiance (W sr^-1 m^-2, MTL's Ke) from the float properties
// `emission_red`, `emission_green`, `emission_blue`, of the face or averaged from its
// vertices. A file with colours or emission gives each face a material, the faces of equal
// values sharing one; the half not given is 0, as in MTL. A file with neither leaves its faces
// without a material (a scene file's default_material gives them one). Other elements and
// properties are skipped.
#pragma once

#include <filesystem>

#include "meshes/polygon_soup.h"

namespace hmcr {

// The PLY's polygons and materials. Throws InputError "path:line: why" (ascii) or "path: face
// N: why" (binary) on a file that is not valid PLY or not one hmcr reads.
PolygonSoup read_ply(const std::filesystem::path& ply);

}  // namespace hmcr
