// SPDX-License-Identifier: Apache-2.0
// The density map's documented colour ramp (image/density_map.h), at its stops and between.
#include "image/density_map.h"

#include <gtest/gtest.h>

namespace hmcr::test {
namespace {

TEST(DensityMap, RampStopsAndScale) {
    EXPECT_EQ(density_colour(1), (Srgb8{0, 0, 96}));       // t = 0
    EXPECT_EQ(density_colour(0), (Srgb8{0, 0, 96}));       // no samples: the bottom
    EXPECT_EQ(density_colour(4), (Srgb8{0, 0, 255}));      // t = 0.2
    EXPECT_EQ(density_colour(16), (Srgb8{0, 255, 255}));   // t = 0.4
    EXPECT_EQ(density_colour(32), (Srgb8{0, 255, 128}));   // t = 0.5, half-way to green
    EXPECT_EQ(density_colour(64), (Srgb8{0, 255, 0}));     // t = 0.6
    EXPECT_EQ(density_colour(256), (Srgb8{255, 255, 0}));  // t = 0.8
    EXPECT_EQ(density_colour(1024), (Srgb8{255, 0, 0}));   // t = 1
    EXPECT_EQ(density_colour(5000), (Srgb8{255, 0, 0}));   // clamped
}

TEST(DensityMap, OnePixelPerCount) {
    const Image8 map = density_map({1, 4, 1024, 64, 16, 256}, 3, 2);
    EXPECT_EQ(map.at(2, 0), (Srgb8{255, 0, 0}));
    EXPECT_EQ(map.at(0, 1), (Srgb8{0, 255, 0}));
    EXPECT_THROW(density_map({1, 2}, 3, 2), std::invalid_argument);
}

}  // namespace
}  // namespace hmcr::test
