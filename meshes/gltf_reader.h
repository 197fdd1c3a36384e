// SPDX-License-Identifier: Apache-2.0
// glTF 2.0 (.gltf with its buffers, or the binary .glb), parsed by TinyGLTF (docs/decisions.md),
// its meshes placed by the nodes of its scene (docs/design.md §11.12). Read: the triangles of
// every primitive of mode triangles, strip or fan (points and lines are skipped with a warning),
// from a float VEC3 POSITION accessor and optional indices; a transformation whose determinant is
// negative turns the triangles over, as the specification says. Positions are single precision
// and are read as meshes/single_precision.h says; the two triangles of a quad split as a fan are
// one quad again (meshes/fan_quads.h). Materials as meshes/gltf_materials.h says; a primitive
// without a material has none (a scene file's default_material gives it one).
#pragma once

#include <cstddef>
#include <filesystem>

#include "meshes/polygon_soup.h"

namespace hmcr {

struct GltfOptions {
    // Triangles the nodes may place (and three times as many vertices): a node placing a mesh
    // is a dozen bytes of JSON, so a small file may place a large mesh any number of times.
    // MGF's limit (meshes/mgf_reader.h).
    std::size_t max_polygons = 50'000'000;
};

// The glTF's polygons and materials. Throws InputError "path: why" on a file that is not valid
// glTF or not one hmcr reads; a face is placed as "path: face N", N counted over the scene.
PolygonSoup read_gltf(const std::filesystem::path& gltf, const GltfOptions& options = {});

}  // namespace hmcr
