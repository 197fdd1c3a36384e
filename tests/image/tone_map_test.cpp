// SPDX-License-Identifier: Apache-2.0
#include "image/tone_map.h"

#include <gtest/gtest.h>

#include <limits>

#include "image/image.h"  // Srgb8

namespace hmcr {
namespace {

TEST(ToneMap, SrgbTransferFunction) {
    EXPECT_EQ(srgb_encode(0), 0);
    EXPECT_DOUBLE_EQ(srgb_encode(0.001), 12.92 * 0.001);  // the linear segment
    // Both segments meet at the breakpoint (to the precision of the standard's constants).
    EXPECT_NEAR(srgb_encode(0.0031308), 1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, 1e-7);
    EXPECT_DOUBLE_EQ(srgb_encode(0.5), 1.055 * std::pow(0.5, 1 / 2.4) - 0.055);
    EXPECT_DOUBLE_EQ(srgb_encode(1), 1);
    EXPECT_DOUBLE_EQ(srgb_encode(7), 1);   // clamped
    EXPECT_DOUBLE_EQ(srgb_encode(-1), 0);  // clamped
}

TEST(ToneMap, EightBitValues) {
    EXPECT_EQ(to_srgb8(Rgb(0, 0, 0), 1), (Srgb8{0, 0, 0}));
    EXPECT_EQ(to_srgb8(Rgb(1, 2, 0.5), 1), (Srgb8{255, 255, 188}));
    // 0.0031308 -> 10.31, 0.001 -> 3.29, 0.18 (middle grey) -> 117.6.
    EXPECT_EQ(to_srgb8(Rgb(0.0031308, 0.001, 0.18), 1), (Srgb8{10, 3, 118}));
    EXPECT_EQ(to_srgb8(Rgb(0.25, 0.036, 0.09), 2), (Srgb8{188, 76, 118}));  // exposure scales
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(to_srgb8(Rgb(nan, 1, 0), 1), (Srgb8{0, 255, 0}));
}

TEST(ToneMap, LuminanceWeights) {
    EXPECT_DOUBLE_EQ(luminance(Rgb(1, 0, 0)), 0.2126);
    EXPECT_DOUBLE_EQ(luminance(Rgb(0, 1, 0)), 0.7152);
    EXPECT_DOUBLE_EQ(luminance(Rgb(0, 0, 1)), 0.0722);
}

}  // namespace
}  // namespace hmcr
