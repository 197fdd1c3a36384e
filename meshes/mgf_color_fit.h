// SPDX-License-Identifier: Apache-2.0
// How an MGF colour becomes a reflectance in RGB (docs/design.md §1.7): a colour outside the RGB
// gamut, or brighter than a real diffuser in a channel, moves toward the grey of its luminance
// until it fits; a diffuse and a specular colour that fit alone but sum above 1 in a channel
// move toward their greys together. Luminances are kept. The reader counts the colours moved.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <utility>

#include "meshes/mgf_color.h"

namespace hmcr {

// The largest channel of a coloured reflectance moved toward grey to fit RGB: Spectralon's,
// the highest of real diffusers (a channel of 1 would absorb nothing).
inline constexpr double kMaxColouredReflectance = 0.99;

struct FittedColour {
    Eigen::Vector3d rgb;
    bool moved = false;  // toward grey, to fit
};

// The RGB of a colour of chromaticity c and luminance Y, every channel in [0, upper].
FittedColour fit_colour(const Chromaticity& c, double luminance, double upper);

// The diffuse kd (luminance rd) and specular ks (luminance rs) moved toward their greys together
// until every channel of their sum fits as a diffuse colour's does alone; nullopt where nothing
// moves: the sum fits, or rd + rs is above 1, which is the specular repair's
// (meshes/repairs.cpp).
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> fit_sum(const Eigen::Vector3d& kd,
                                                                   double rd,
                                                                   const Eigen::Vector3d& ks,
                                                                   double rs);

}  // namespace hmcr
