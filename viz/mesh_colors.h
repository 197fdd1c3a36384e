// SPDX-License-Identifier: Apache-2.0
// The tone mapping of image/tone_map.h applied to a solution's Gouraud mesh: the exposure of a
// mesh, and the `RadiosityColor` of its points.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "radiosity/shaded_mesh.h"

namespace hmcr {

// Scale factor on radiance that maps the area-weighted mean cell luminance to kMiddleGrey;
// 1 when the mesh is black (or empty).
double auto_exposure(const ShadedMesh& mesh);

// RadiosityColor of every point of the mesh, with auto_exposure(mesh).
std::vector<std::array<std::uint8_t, 3>> point_colors(const ShadedMesh& mesh);

}  // namespace hmcr
