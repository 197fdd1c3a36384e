// SPDX-License-Identifier: Apache-2.0
// The patch mesh's connectivity as plain arrays: which mesh vertex each face corner is, and
// which mesh edge each face side is. 16 bytes a face each, where the OpenMesh mesh takes about
// 115: `hmcr solve` keeps these and releases the mesh before it shoots the rays
// (docs/performance.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "meshes/patch_mesh.h"

namespace hmcr {

inline constexpr std::uint32_t kNoCorner = 0xffffffffu;  // corner 3 of a triangle

// Corner k of face f is mesh vertex faces[f][k], in the order OpenMesh circulates the face.
struct FaceVertices {
    std::vector<std::array<std::uint32_t, 4>> faces;
    std::uint32_t vertex_count = 0;

    int corner_count(std::size_t f) const { return faces[f][3] == kNoCorner ? 3 : 4; }
};

// Side k of face f (from corner k to corner k + 1) is mesh edge faces[f][k]. Edges are numbered
// in order of first appearance, face by face and side by side, as OpenMesh numbers them when
// the faces are added in order.
struct FaceEdges {
    std::vector<std::array<std::uint32_t, 4>> faces;
    std::uint32_t edge_count = 0;
};

// Throws std::invalid_argument on a face with fewer than 3 or more than 4 corners.
FaceVertices face_vertices(const PatchMesh& mesh);
// Throws std::length_error when the sides do not fit 32-bit numbers.
FaceEdges face_edges(const FaceVertices& vertices);

}  // namespace hmcr
