// SPDX-License-Identifier: Apache-2.0
// The glossy lobe's sampling against its stated density (trace/ward_lobe.h): a chi-square test
// of 200,000 directions binned in (cos theta, phi) about the normal against the density
// integrated over each bin, the directions lost below the surface a bin of their own; and the
// lobe's value where it is known.
#include "trace/ward_lobe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "rays/rng.h"
#include "rays/sampling.h"
#include "tests/support/statistics.h"

namespace hmcr::test::ward_lobe_tests {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kZBins = 32, kPhiBins = 64;

// 8-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kNodes[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                              -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                              0.7966664774136267,  0.9602898564975363};
constexpr double kWeights[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                0.2223810344533745, 0.1012285362903763};

struct Frame {
    Vec3 n, t, b;
    Vec3 direction(double z, double phi) const {
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        return r * std::cos(phi) * t + r * std::sin(phi) * b + z * n;
    }
};

int bin_of(const Frame& f, const Vec3& w) {
    const double z = std::clamp(f.n.dot(w), 0.0, 1.0);
    double phi = std::atan2(f.b.dot(w), f.t.dot(w));
    if (phi < 0) phi += 2 * kPi;
    const int i = std::min(kZBins - 1, int(z * kZBins));
    const int j = std::min(kPhiBins - 1, int(phi / (2 * kPi) * kPhiBins));
    return i * kPhiBins + j;
}

// The chi-square test of directions sampled at `alpha` against the density at `density_alpha`
// (the same for the real test), wo at theta_o from the normal.
testing::AssertionResult sampling_matches_density(double alpha, double density_alpha,
                                                  double theta_o, int comparisons) {
    Frame f;
    f.n = Vec3(0.3, -0.5, 0.8).normalized();  // any normal: the frame must not matter
    tangent_frame(f.n, f.t, f.b);
    const Vec3 wo = f.direction(std::cos(theta_o), 0.7);
    // Expected: the density over each bin (dw = dz dphi), by 8 x 8 Gauss-Legendre.
    const std::size_t samples = 200'000;
    std::vector<double> expected(kZBins * kPhiBins + 1, 0.0), observed(expected.size(), 0.0);
    double inside = 0;
    for (int i = 0; i < kZBins; ++i)
        for (int j = 0; j < kPhiBins; ++j) {
            const double z0 = double(i) / kZBins, dz = 1.0 / kZBins;
            const double p0 = 2 * kPi * j / kPhiBins, dp = 2 * kPi / kPhiBins;
            double integral = 0;
            for (int a = 0; a < 8; ++a)
                for (int c = 0; c < 8; ++c) {
                    const double z = z0 + dz * (kNodes[a] + 1) / 2;
                    const double phi = p0 + dp * (kNodes[c] + 1) / 2;
                    integral += kWeights[a] * kWeights[c] / 4 * dz * dp *
                                ward_lobe_pdf(f.n, wo, f.direction(z, phi), density_alpha);
                }
            expected[i * kPhiBins + j] = integral * samples;
            inside += integral;
        }
    expected.back() = std::max(0.0, 1 - inside) * samples;  // directions lost below the surface
    Rng rng(7, std::uint64_t(alpha * 1000), std::uint64_t(theta_o * 1000));
    for (std::size_t k = 0; k < samples; ++k) {
        const double xi1 = rng.uniform(), xi2 = rng.uniform();
        const auto w = sample_ward_lobe(f.n, wo, alpha, xi1, xi2);
        observed[w ? bin_of(f, *w) : kZBins * kPhiBins] += 1;
    }
    return chi_square_test(
        "alpha " + std::to_string(alpha) + ", theta_o " + std::to_string(theta_o), observed,
        expected, comparisons);
}

TEST(WardLobe, SamplingPassesAChiSquareTestAgainstItsDensity) {
    const double alphas[] = {0.1, 0.3}, thetas[] = {0.0, 0.9, 1.35};
    for (double alpha : alphas)
        for (double theta : thetas) EXPECT_TRUE(sampling_matches_density(alpha, alpha, theta, 6));
}

// The test can tell: a density 5% too wide is rejected.
TEST(WardLobe, TheChiSquareTestRejectsADensityOfAnotherRoughness) {
    EXPECT_FALSE(sampling_matches_density(0.2, 0.21, 0.6, 1));
}

// At the mirror direction tan(theta_h) = 0: f / rho_s = 1 / (4 pi alpha^2 cos theta); the value
// is symmetric in wo and wi, 0 below the surface, and the density integrates to at most 1.
TEST(WardLobe, ValueAtTheMirrorDirectionReciprocityAndHorizon) {
    const Vec3 n(0, 0, 1), wo = Vec3(0.6, 0, 0.8), mirror(-0.6, 0, 0.8),
                           wi = Vec3(-0.3, 0.2, 0.9).normalized();
    const double alpha = 0.2;
    EXPECT_NEAR(ward_lobe(n, wo, mirror, alpha), 1 / (4 * kPi * alpha * alpha * 0.8), 1e-12);
    EXPECT_DOUBLE_EQ(ward_lobe(n, wo, wi, alpha), ward_lobe(n, wi, wo, alpha));
    EXPECT_EQ(ward_lobe(n, wo, Vec3(0, 0.6, -0.8), alpha), 0);
    EXPECT_EQ(ward_lobe_pdf(n, wo, Vec3(0, 0.6, -0.8), alpha), 0);
}

}  // namespace
}  // namespace hmcr::test::ward_lobe_tests
