// SPDX-License-Identifier: Apache-2.0
// Wavefront MTL material libraries (docs/design.md §11.2): `newmtl NAME` starts a material,
// `Kd r g b` and `Ke r g b` set its reflectance and emitted radiance, and `Ks r g b` its mirror
// reflectance when the material has `illum 3` (illum 0 to 2 leave Ks unused; other illumination
// models are refused); the other statements of the common readers are ignored, and unknown ones
// are warned about, once per statement name with their count (a `KE` typed for `Ke` would
// otherwise turn a light off without a word).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "meshes/polygon_soup.h"

namespace hmcr {

// A material read: its index in PolygonSoup::materials and the place of its `newmtl`.
struct MaterialName {
    std::int32_t index = 0;
    SourcePlace defined;
};
// The materials read so far, in every library, by name.
using MaterialNames = std::map<std::string, MaterialName, std::less<>>;

// Reads the MTL text of soup.files[file]: appends its materials to soup.materials, in file
// order, with the places of their Kd, Ke and Ks, and its warnings to soup.warnings. Throws
// InputError "path:line: why" on a statement that is not valid MTL and on a material whose name
// is already in `names` (which gains every name read).
void read_mtl(std::string_view text, std::uint32_t file, PolygonSoup& soup, MaterialNames& names);

}  // namespace hmcr
