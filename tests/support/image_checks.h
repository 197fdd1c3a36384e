// SPDX-License-Identifier: Apache-2.0
// Exact comparison of linear images for the viz tests (Eigen's == on Rgb is per channel).
#pragma once

#include <gtest/gtest.h>

#include "image/image.h"

namespace hmcr::test {

// Embree intersects in float: hit coordinates, distances and the values interpolated from them
// carry about 1e-7 relative error.
constexpr double kFloatTol = 1e-6;

// Same size and bitwise the same value in every channel of every pixel.
inline testing::AssertionResult identical(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) {
        return testing::AssertionFailure() << "sizes differ: " << a.width << " x " << a.height
                                           << " and " << b.width << " x " << b.height;
    }
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if ((a.pixels[i] != b.pixels[i]).any()) {
            return testing::AssertionFailure()
                   << "pixel " << i << " differs: " << a.pixels[i].transpose() << " and "
                   << b.pixels[i].transpose();
        }
    }
    return testing::AssertionSuccess();
}

}  // namespace hmcr::test
