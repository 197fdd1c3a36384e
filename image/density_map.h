// SPDX-License-Identifier: Apache-2.0
// The sampling density map of an adaptive image (the papers' "supersampling temperature map"):
// each pixel coloured by how many samples it got, warm for many, cold for few.
//
// Scale: t = log2(n) / 10, clamped to [0, 1], the same for every sampler and image so that
// maps can be compared side by side: 1 sample is t = 0, 4 is 0.2, 8 is 0.3, 60 is 0.59, 480 is
// 0.89, 1,024 and more are 1. Ramp: piecewise linear in sRGB through dark blue (0, 0, 96) at
// t = 0, blue (0, 0, 255) at 0.2, cyan (0, 255, 255) at 0.4, green (0, 255, 0) at 0.6, yellow
// (255, 255, 0) at 0.8 and red (255, 0, 0) at 1.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace hmcr {

Srgb8 density_colour(double samples);

// samples: one count per pixel, row-major. Throws std::invalid_argument on a size mismatch.
Image8 density_map(const std::vector<std::uint32_t>& samples, int width, int height);

}  // namespace hmcr
