// SPDX-License-Identifier: Apache-2.0
// widen_float (single_precision.h).
#include "meshes/single_precision.h"

#include <array>
#include <charconv>
#include <cmath>

namespace hmcr {

double widen_float(float value) {
    if (!std::isfinite(value)) return double(value);
    std::array<char, 64> text;
    const auto written = std::to_chars(text.data(), text.data() + text.size(), value);
    double wide = 0;
    std::from_chars(text.data(), written.ptr, wide);
    return wide;
}

}  // namespace hmcr
