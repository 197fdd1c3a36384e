// SPDX-License-Identifier: Apache-2.0
#include "trace/criteria/luminances.h"

#include <cmath>

#include "image/tone_map.h"

namespace hmcr {

Luminances luminances(std::span<const PixelSample> samples) {
    Luminances l;
    l.values.reserve(samples.size());
    for (const PixelSample& s : samples) {
        l.values.push_back(luminance(s.radiance));
        l.sum += l.values.back();
    }
    return l;
}

double divergence_value(std::span<const PixelSample> samples, Divergence f, bool square_root) {
    const Luminances l = luminances(samples);
    if (!(l.sum > 0)) return 0;
    const double d = f(l.values, l.sum);
    return l.mean() * (square_root ? std::sqrt(d) : d) / l.n();
}

}  // namespace hmcr
