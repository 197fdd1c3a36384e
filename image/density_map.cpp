// SPDX-License-Identifier: Apache-2.0
#include "image/density_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace hmcr {
namespace {

constexpr std::array<std::array<double, 3>, 6> kRamp = {
    {{0, 0, 96}, {0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}}};

}  // namespace

Srgb8 density_colour(double samples) {
    const double t = std::clamp(std::log2(std::max(samples, 1.0)) / 10, 0.0, 1.0);
    const double x = t * double(kRamp.size() - 1);
    const std::size_t i = std::min(std::size_t(x), kRamp.size() - 2);
    const double f = x - double(i);
    Srgb8 c;
    for (int k = 0; k < 3; ++k) {
        c[k] = std::uint8_t(std::lround((1 - f) * kRamp[i][k] + f * kRamp[i + 1][k]));
    }
    return c;
}

Image8 density_map(const std::vector<std::uint32_t>& samples, int width, int height) {
    if (width <= 0 || height <= 0 || samples.size() != std::size_t(width) * std::size_t(height)) {
        throw std::invalid_argument("density map: counts do not match the image size");
    }
    Image8 map(width, height);
    for (std::size_t i = 0; i < samples.size(); ++i) map.pixels[i] = density_colour(samples[i]);
    return map;
}

}  // namespace hmcr
