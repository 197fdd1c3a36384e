// SPDX-License-Identifier: Apache-2.0
#include "image/tone_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hmcr {

double luminance(const Rgb& c) {
    return kLuminanceWeights[0] * c[0] + kLuminanceWeights[1] * c[1] + kLuminanceWeights[2] * c[2];
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

}  // namespace hmcr
