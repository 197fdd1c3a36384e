#include "viz/tone_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hmcr {

double luminance(const Rgb& c) {
    return kLuminanceWeights[0] * c[0] + kLuminanceWeights[1] * c[1] + kLuminanceWeights[2] * c[2];
}

double auto_exposure(const ShadedMesh& mesh) {
    double weighted = 0, area = 0;
    for (std::size_t c = 0; c < mesh.element_radiosity.size(); ++c) {
        weighted += mesh.element_area[c] * luminance(mesh.element_radiosity[c] / std::numbers::pi);
        area += mesh.element_area[c];
    }
    if (!(area > 0) || !(weighted > 0)) return 1.0;
    return kMiddleGrey / (weighted / area);
}

double srgb_encode(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    if (c <= 0.0031308) return 12.92 * c;
    return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

std::array<std::uint8_t, 3> to_srgb8(const Rgb& radiance, double exposure) {
    std::array<std::uint8_t, 3> out{};
    for (int k = 0; k < 3; ++k) {
        // NaN would survive the clamp; show it as black rather than as undefined behaviour.
        const double x = std::isnan(radiance[k]) ? 0.0 : exposure * radiance[k];
        out[k] = std::uint8_t(std::lround(255.0 * srgb_encode(x)));
    }
    return out;
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
