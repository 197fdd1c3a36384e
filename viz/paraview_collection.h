// SPDX-License-Identifier: Apache-2.0
// A ParaView collection file (.pvd): several .vtp files as the time steps of one source, so
// that ParaView steps through them with its time controls (a study's meshes, one per cell).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hmcr {

struct CollectionEntry {
    std::filesystem::path file;  // relative to the .pvd's folder
    std::string name;            // shown by ParaView for the step
};

// Entry k is time step k.
std::string paraview_collection(const std::vector<CollectionEntry>& entries);

// Writes paraview_collection() atomically.
void write_paraview_collection(const std::filesystem::path& pvd,
                               const std::vector<CollectionEntry>& entries);

}  // namespace hmcr
