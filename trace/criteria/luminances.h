// SPDX-License-Identifier: Apache-2.0
// The luminances of a pixel's samples, the distribution the f-divergence, contrast and
// variance criteria look at (Rigau 2003, eq. 24: p_i = L_i / sum L_i).
#pragma once

#include <span>
#include <vector>

#include "trace/criteria/criterion.h"

namespace hmcr {

struct Luminances {
    std::vector<double> values;  // Rec. 709 luminance of each sample, as the RMSEp weights
    double sum = 0;

    double n() const { return double(values.size()); }
    double mean() const { return sum / n(); }  // L-bar, eq. 26
};

Luminances luminances(std::span<const PixelSample> samples);

// The f-divergence criteria: L-bar f(p, q) / n (eq. 25) or, with square_root, L-bar
// sqrt(f(p, q)) / n (eqs. 27-29), for a divergence f from the uniform distribution
// (oracles/divergences.h); 0 for a black pixel.
using Divergence = double (*)(std::span<const double> w, double sum);
double divergence_value(std::span<const PixelSample> samples, Divergence f, bool square_root);

}  // namespace hmcr
