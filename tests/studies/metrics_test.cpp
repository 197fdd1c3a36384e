// SPDX-License-Identifier: Apache-2.0
#include "studies/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hmcr {
namespace {

Image8 two_pixels(Srgb8 a, Srgb8 b) {
    Image8 im(2, 1);
    im.pixels = {a, b};
    return im;
}

TEST(Metrics, HandComputedErrors) {
    // Differences: pixel 0 (3, -4, 0), pixel 1 (0, 0, 5).
    const Image8 a = two_pixels({10, 20, 30}, {0, 0, 0});
    const Image8 b = two_pixels({13, 16, 30}, {0, 0, 5});
    // RMSEa = sqrt((9 + 16 + 25) / 6); RMSEp = sqrt((0.2126 * 9 + 0.7152 * 16 + 0.0722 * 25) / 2).
    const double ra = std::sqrt(50.0 / 6), rp = std::sqrt(15.1616 / 2);
    EXPECT_NEAR(rmse_a(a, b), ra, 1e-12);
    EXPECT_NEAR(rmse_p(a, b), rp, 1e-12);
    const ImageErrors e = image_errors(a, b);
    EXPECT_NEAR(e.rmse_a, ra, 1e-12);
    EXPECT_NEAR(e.rmse_p, rp, 1e-12);
    EXPECT_NEAR(e.psnr_a, 20 * std::log10(255 / ra), 1e-12);  // 38.92 dB
    EXPECT_NEAR(e.psnr_p, 20 * std::log10(255 / rp), 1e-12);  // 39.33 dB
    EXPECT_NEAR(e.psnr_a, 38.9226, 1e-4);
    EXPECT_EQ(rmse_a(b, a), rmse_a(a, b));  // symmetric
}

// Two images 3 and 1 above the reference in every channel: MSE of one 5 on average, of their
// mean 4; so bias^2 = 2 * 4 - 5 = 3 and noise^2 = 5 - 3 = 2.
TEST(Metrics, ErrorSplitsIntoBiasAndNoise) {
    const Image8 ref = two_pixels({100, 100, 100}, {50, 50, 50});
    const Image8 a = two_pixels({103, 103, 103}, {53, 53, 53});
    const Image8 b = two_pixels({101, 101, 101}, {51, 51, 51});
    const ErrorSplit e = split_error({a, b}, ref);
    EXPECT_NEAR(e.bias, std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(e.noise, std::sqrt(2.0), 1e-12);
    const ErrorSplit same = split_error({a, a, a}, ref);  // no spread: all bias
    EXPECT_NEAR(same.bias, 3, 1e-12);
    EXPECT_NEAR(same.noise, 0, 1e-12);
    EXPECT_THROW(split_error({a}, ref), std::invalid_argument);
}

TEST(Metrics, UniformErrorGivesTheSameRmseForBothWeightings) {
    // The luminance weights sum to 1: an error of 1 everywhere is an RMSE of 1 for both.
    const Image8 a = two_pixels({1, 1, 1}, {200, 100, 50});
    const Image8 b = two_pixels({2, 2, 2}, {201, 101, 51});
    EXPECT_NEAR(rmse_a(a, b), 1, 1e-15);
    EXPECT_NEAR(rmse_p(a, b), 1, 1e-15);
    EXPECT_NEAR(psnr(1), 20 * std::log10(255.0), 1e-12);  // 48.13 dB
    EXPECT_NEAR(psnr(255), 0, 1e-15);
}

TEST(Metrics, IdenticalImagesHaveInfinitePsnr) {
    const Image8 a = two_pixels({10, 20, 30}, {40, 50, 60});
    const ImageErrors e = image_errors(a, a);
    EXPECT_EQ(e.rmse_a, 0);
    EXPECT_EQ(e.rmse_p, 0);
    EXPECT_EQ(e.psnr_a, std::numeric_limits<double>::infinity());
    EXPECT_EQ(e.psnr_p, std::numeric_limits<double>::infinity());
}

TEST(Metrics, RejectsImagesOfDifferentSizes) {
    const Image8 a = two_pixels({0, 0, 0}, {0, 0, 0});
    EXPECT_THROW(rmse_a(a, Image8(1, 2)), std::invalid_argument);
    EXPECT_THROW(image_errors(Image8{}, Image8{}), std::invalid_argument);
}

}  // namespace
}  // namespace hmcr
