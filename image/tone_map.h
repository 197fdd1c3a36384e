// SPDX-License-Identifier: Apache-2.0
// Tone mapping of linear radiosity to 8-bit sRGB for `RadiosityColor` and rendered images.
//
// Radiance L = B / pi (Lambertian surfaces). One fixed exposure per mesh maps the area-weighted
// mean luminance to middle grey, 0.18 (Reinhard et al. 2002, "Photographic tone reproduction for
// digital images", the key value a = 0.18); then clamp to 1 and apply the sRGB transfer function
// of IEC 61966-2-1.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/types.h"

namespace hmcr {

inline constexpr double kMiddleGrey = 0.18;

// Relative luminance of linear Rec. 709 / sRGB primaries: these weights times the channels.
inline constexpr double kLuminanceWeights[3] = {0.2126, 0.7152, 0.0722};
double luminance(const Rgb& c);

// sRGB encoding of one linear value in [0, 1] (clamped), in [0, 1].
double srgb_encode(double linear);

// exposure * radiance, clamped, sRGB-encoded and rounded to 8 bits per channel.
std::array<std::uint8_t, 3> to_srgb8(const Rgb& radiance, double exposure);

}  // namespace hmcr
