// Reading a solution back from its .vtp (SPEC section 5) for rendering and comparison.
#pragma once

#include <filesystem>

#include "viz/shaded_mesh.h"

namespace hmcr {

// The ShadedMesh an hmcr .vtp holds. Throws std::invalid_argument naming the file when it cannot
// be read or lacks the hmcr arrays.
ShadedMesh read_vtp(const std::filesystem::path& path);

}  // namespace hmcr
