// SPDX-License-Identifier: Apache-2.0
// glTF materials as hmcr's (docs/design.md §11.12): the diffuse reflectance is the base colour
// factor's RGB times 1 - metallicFactor (the metal part is absorbed, with a warning); the emitted
// radiance (W sr^-1 m^-2, MTL's Ke) the emissive factor times KHR_materials_emissive_strength's
// emissiveStrength (1 without it); doubleSided gives 2 sides, else 1. Textures are not read
// (one warning a material names them); nor are alpha and other extensions.
#pragma once

#include <cstdint>
#include <string>

#include "meshes/polygon_soup.h"

namespace tinygltf {
class Model;
}

namespace hmcr {

// Appends every material of the model to soup.materials, in order, placed at soup.files[file],
// with their warnings. Throws InputError "path: materials[N]: why" for a factor of the wrong
// length or an emissive strength that is not a number of at least 0.
void read_gltf_materials(const tinygltf::Model& model, std::uint32_t file, PolygonSoup& soup);

}  // namespace hmcr
