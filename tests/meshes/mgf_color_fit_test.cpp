// SPDX-License-Identifier: Apache-2.0
#include "meshes/mgf_color_fit.h"

#include <gtest/gtest.h>

namespace hmcr {
namespace {

constexpr double kTol = 1e-12;

TEST(MgfColourFit, AColourThatFitsIsKeptAndOneThatDoesNotKeepsItsLuminance) {
    const FittedColour grey = fit_colour(Chromaticity{1.0 / 3, 1.0 / 3}, 0.5, 0.99);
    EXPECT_FALSE(grey.moved);
    EXPECT_TRUE(grey.rgb.isApprox(Eigen::Vector3d::Constant(0.5)));
    // A pale colour fits as it is.
    const FittedColour pale = fit_colour(Chromaticity{0.34, 0.34}, 0.3, 0.99);
    EXPECT_FALSE(pale.moved);
    EXPECT_TRUE(pale.rgb.isApprox(chromaticity_rgb(Chromaticity{0.34, 0.34}, 0.3)));
    // A saturated green at a high luminance leaves the gamut: it moves toward grey, every
    // channel ends in [0, upper] and one at a bound, and its luminance stays.
    const FittedColour green = fit_colour(Chromaticity{0.2, 0.7}, 0.8, 0.99);
    EXPECT_TRUE(green.moved);
    EXPECT_GE(green.rgb.minCoeff(), 0.0);
    EXPECT_LE(green.rgb.maxCoeff(), 0.99 + kTol);
    EXPECT_TRUE(green.rgb.minCoeff() < kTol || green.rgb.maxCoeff() > 0.99 - kTol);
    EXPECT_NEAR(rgb_luminance(green.rgb), 0.8, 1e-9);
    // No luminance to scale (y = 0): the grey.
    const FittedColour none = fit_colour(Chromaticity{0.3, 0.0}, 0.4, 0.99);
    EXPECT_TRUE(none.moved);
    EXPECT_TRUE(none.rgb.isApprox(Eigen::Vector3d::Constant(0.4)));
}

TEST(MgfColourFit, ADiffuseAndASpecularColourMoveTogetherUntilTheirSumFits) {
    const Eigen::Vector3d kd(0.9, 0.2, 0.1), ks(0.3, 0.3, 0.3);
    const double rd = rgb_luminance(kd), rs = 0.3;
    const auto fitted = fit_sum(kd, rd, ks, rs);
    ASSERT_TRUE(fitted);
    const auto& [d, s] = *fitted;
    EXPECT_NEAR((d + s).maxCoeff(), kMaxColouredReflectance, kTol);
    EXPECT_NEAR(rgb_luminance(d), rd, 1e-9);
    EXPECT_NEAR(rgb_luminance(s), rs, 1e-9);
    // Both keep the same share of their colour: each is its grey plus t times its difference.
    const double t =
        (d - Eigen::Vector3d::Constant(rd)).norm() / (kd - Eigen::Vector3d::Constant(rd)).norm();
    EXPECT_GT(t, 0);
    EXPECT_LT(t, 1);
    EXPECT_TRUE((s - Eigen::Vector3d::Constant(rs))
                    .isApprox(t * (ks - Eigen::Vector3d::Constant(rs)), 1e-9) ||
                (ks - Eigen::Vector3d::Constant(rs)).norm() < kTol);
    // A sum that fits moves nothing; luminances above 1 are the specular repair's.
    EXPECT_FALSE(fit_sum(Eigen::Vector3d(0.5, 0.2, 0.1), 0.25, ks, rs));
    EXPECT_FALSE(fit_sum(kd, 0.8, ks, 0.3));
}

}  // namespace
}  // namespace hmcr
