// SPDX-License-Identifier: Apache-2.0
#include "viz/mesh_colors.h"

#include <numbers>

#include "image/tone_map.h"

namespace hmcr {

double auto_exposure(const ShadedMesh& mesh) {
    double weighted = 0, area = 0;
    for (std::size_t c = 0; c < mesh.element_radiosity.size(); ++c) {
        weighted += mesh.element_area[c] * luminance(mesh.element_radiosity[c] / std::numbers::pi);
        area += mesh.element_area[c];
    }
    if (!(area > 0) || !(weighted > 0)) return 1.0;
    return kMiddleGrey / (weighted / area);
}

std::vector<std::array<std::uint8_t, 3>> point_colors(const ShadedMesh& mesh) {
    const double exposure = auto_exposure(mesh);
    std::vector<std::array<std::uint8_t, 3>> colors;
    colors.reserve(mesh.point_radiosity.size());
    for (const Rgb& b : mesh.point_radiosity) {
        colors.push_back(to_srgb8(b / std::numbers::pi, exposure));
    }
    return colors;
}

}  // namespace hmcr
