// SPDX-License-Identifier: Apache-2.0
// The solution as VTK XML PolyData (.vtp, appended raw, LZ4), with the arrays of
// docs/design.md §5, for ParaView.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "radiosity/shaded_mesh.h"

namespace hmcr {

// Run description stored as field data (one tuple per array).
struct VtpMetadata {
    std::string oracle;               // Oracle
    double epsilon = 0;               // Epsilon
    std::uint64_t lines = 0;          // Lines
    std::uint64_t rays = 0;           // Rays
    std::uint64_t seed = 0;           // Seed
    std::uint64_t element_count = 0;  // ElementCount: cells, the hierarchy's leaves
    std::uint64_t mesh_leaves = 0;    // MeshLeaves: the mesh's leaves (a cluster leaf is one)
    std::uint64_t iterations = 0;     // Iterations
    double time_value = 0;            // TimeValue (ParaView's time of this file)
    std::string scene;                // Scene: its name
    std::uint64_t patch_count = 0;    // PatchCount: the scene's patches
    std::string geometry_hash;        // GeometryHash: geometry_hash() of the scene's mesh
    std::string link_weight;          // LinkWeight: the solve's link_weight setting
    std::string clustering = "none";  // Clustering: the solve's clustering setting
};

// Writes `mesh` atomically; RadiosityColor is tone-mapped with auto_exposure(mesh). Throws
// std::runtime_error naming the file on failure, leaving no file behind.
void write_vtp(const std::filesystem::path& path, const ShadedMesh& mesh, const VtpMetadata& meta);

}  // namespace hmcr
