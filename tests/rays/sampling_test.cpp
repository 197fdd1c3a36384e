// SPDX-License-Identifier: Apache-2.0
// Samplers against their densities: each is a hypothesis test with binomial or sample
// standard errors.
#include "rays/sampling.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <numeric>

#include "radiosity/hierarchy.h"
#include "rays/alias_table.h"
#include "rays/element_sampler.h"
#include "rays/rng.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

constexpr int kSamples = 400'000;

TEST(Sampling, LinearDensityPutsTheRightMassInEachBin) {
    Rng rng(1, 0);
    const double a = 0.2, b = 3.0;
    constexpr int kBins = 10;
    std::array<int, kBins> count{};
    for (int k = 0; k < kSamples; ++k) {
        const double x = sample_linear(a, b, rng.uniform());
        ASSERT_GE(x, 0);
        ASSERT_LE(x, 1);
        ++count[std::min(kBins - 1, int(x * kBins))];
    }
    for (int i = 0; i < kBins; ++i) {
        // Mass of bin i: C(x1) - C(x0) for the CDF C(x) = (2 a x + (b - a) x^2) / (a + b) of
        // the density 2 ((1 - x) a + x b) / (a + b).
        const auto cdf = [&](double x) { return (2 * a * x + (b - a) * x * x) / (a + b); };
        const double p = cdf(double(i + 1) / kBins) - cdf(double(i) / kBins);
        const double f = double(count[i]) / kSamples;
        EXPECT_TRUE(within_standard_errors("bin " + std::to_string(i), f, p,
                                           std::sqrt(p * (1 - p) / kSamples)));
    }
}

TEST(Sampling, CosineHemisphereHasMeanCosineTwoThirds) {
    Rng rng(2, 0);
    const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
    std::vector<double> cosines(kSamples);
    for (double& c : cosines) {
        const Vec3 d = sample_cosine_hemisphere(n, rng.uniform(), rng.uniform());
        ASSERT_NEAR(d.norm(), 1, 1e-12);
        c = d.dot(n);
        ASSERT_GE(c, 0);
    }
    // E[cos] = integral of cos * cos/pi over the hemisphere = 2/3.
    const Estimate e = estimate_mean(cosines);
    EXPECT_TRUE(within_standard_errors("E[cos theta]", e.mean, 2.0 / 3.0, e.standard_error));
}

// Uniform on the sphere: a cap {d . u > c} holds (1 - c) / 2 of the directions, whatever the
// axis u; the projection on u has mean 0 and mean square 1/3.
TEST(Sampling, UniformSphereFillsEveryCapByItsArea) {
    Rng rng(3, 0);
    const Vec3 u = Vec3(-0.2, 0.9, 0.4).normalized();
    std::vector<double> in_cap(kSamples), along(kSamples), square(kSamples);
    for (std::size_t k = 0; k < kSamples; ++k) {
        const Vec3 d = sample_uniform_sphere(rng.uniform(), rng.uniform());
        ASSERT_NEAR(d.norm(), 1, 1e-12);
        in_cap[k] = d.dot(u) > 0.6;
        along[k] = d.dot(u);
        square[k] = d.dot(u) * d.dot(u);
    }
    const Estimate cap = estimate_mean(in_cap), mean = estimate_mean(along),
                   ms = estimate_mean(square);
    EXPECT_TRUE(within_standard_errors("cap share", cap.mean, 0.2, cap.standard_error));
    EXPECT_TRUE(within_standard_errors("E[d.u]", mean.mean, 0.0, mean.standard_error));
    EXPECT_TRUE(within_standard_errors("E[(d.u)^2]", ms.mean, 1.0 / 3.0, ms.standard_error));
}

// Uniform on the disk: the inner disk of radius 1/2 holds a quarter of the points, and a
// half-plane through the centre holds half.
TEST(Sampling, UniformDiskFillsEveryRegionByItsArea) {
    Rng rng(4, 0);
    std::vector<double> inner(kSamples), half(kSamples);
    for (std::size_t k = 0; k < kSamples; ++k) {
        const Vec2 p = sample_uniform_disk(rng.uniform(), rng.uniform());
        ASSERT_LE(p.norm(), 1.0);
        inner[k] = p.norm() < 0.5;
        half[k] = 0.6 * p.x() - 0.8 * p.y() > 0;
    }
    const Estimate i = estimate_mean(inner), h = estimate_mean(half);
    EXPECT_TRUE(within_standard_errors("inner share", i.mean, 0.25, i.standard_error));
    EXPECT_TRUE(within_standard_errors("half share", h.mean, 0.5, h.standard_error));
}

// On a skewed quad and a triangle, sample_element is uniform by area: each child of the
// sampled element gets a share of the points equal to its share of the area.
TEST(Sampling, ElementSamplesAreUniformByArea) {
    TestPolygon q{
        {{0, 0, 0}, {3, 0, 0}, {2.2, 1.0, 0}, {0.1, 2.5, 0}}, Rgb::Constant(0.5), Rgb::Zero()};
    TestPolygon t{{{4, 0, 0}, {6, 0.5, 0}, {4.5, 2, 0}}, Rgb::Constant(0.5), Rgb::Zero()};
    Hierarchy h(build_patch_set(make_patch_mesh({q, t})), {});
    Rng rng(3, 0);
    for (std::size_t p = 0; p < 2; ++p) {
        Element& parent = h.subdivide(h.root(p))[3];  // a child: a sub-domain, not the patch
        const Element* c = h.subdivide(parent);
        const Patch& patch = h.patch_set().patches[p];
        std::array<int, 4> count{};
        for (int k = 0; k < kSamples; ++k) {
            const Vec2 uv = sample_element(patch, parent.domain, rng.uniform(), rng.uniform());
            ++count[parent.domain.child_containing(patch.is_quad(), uv)];
        }
        for (int k = 0; k < 4; ++k) {
            const double expected = c[k].area / parent.area;
            EXPECT_TRUE(
                within_standard_errors("patch " + std::to_string(p) + " child " + std::to_string(k),
                                       double(count[k]) / kSamples, expected,
                                       std::sqrt(expected * (1 - expected) / kSamples)));
        }
    }
}

TEST(Sampling, AliasTablePicksEachIndexWithItsWeightsShare) {
    const std::vector<double> weights = {5, 0, 1, 0.25, 12, 3, 3, 0.01};
    const AliasTable table(weights);
    Rng rng(4, 0);
    std::vector<int> count(weights.size());
    for (int k = 0; k < kSamples; ++k) ++count[table.sample(rng.uniform())];
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    for (std::size_t i = 0; i < weights.size(); ++i) {
        const double p = weights[i] / total;
        if (p == 0) {
            EXPECT_EQ(count[i], 0) << i;
            continue;
        }
        EXPECT_TRUE(within_standard_errors("index " + std::to_string(i),
                                           double(count[i]) / kSamples, p,
                                           std::sqrt(p * (1 - p) / kSamples)));
    }
}

// Exactly, from the bins: index i is drawn with probability (keep_i + the sum over the bins j
// aliased to i of 1 - keep_j) / n, which must be its weight's share up to rounding. Tables of
// several sizes, each built in the storage of the one before (larger, then smaller).
TEST(Sampling, AliasTableBinsHoldEachIndexsShareExactly) {
    Rng rng(9, 0);
    AliasTable table(std::vector<double>{1.0});
    for (const std::size_t n : {1, 2, 7, 1000, 33, 4096, 5}) {
        std::vector<double> weights(n);
        for (double& w : weights) w = rng.uniform() < 0.2 ? 0.0 : std::pow(10.0, 4 * rng.uniform());
        weights[n / 2] += 1;  // at least one positive weight
        table.assign(weights);
        ASSERT_EQ(table.size(), n);
        const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
        std::vector<double> mass(n, 0.0);
        for (std::size_t j = 0; j < n; ++j) {
            const AliasTable::Bin& b = table.bins()[j];
            ASSERT_GE(b.keep, 0.0);
            ASSERT_LE(b.keep, 1.0);
            ASSERT_LT(b.alias, n);
            mass[j] += b.keep;
            mass[b.alias] += 1 - b.keep;
        }
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(mass[i] / double(n), weights[i] / total, 1e-12)
                << "n " << n << " index " << i;
        }
    }
}

// cos_sin_turn against the library's cos and sin, over the whole turn and at its quarter
// boundaries.
TEST(Sampling, CosSinTurnIsAccurateToTheLastPlaces) {
    Rng rng(8, 0);
    std::vector<double> xis = {0.0, 0.25, 0.5, 0.75, std::nextafter(1.0, 0.0), 0.125, 0.375};
    for (int k = 0; k < 200'000; ++k) xis.push_back(rng.uniform());
    double worst = 0;
    for (const double xi : xis) {
        double c = 0, s = 0;
        cos_sin_turn(xi, c, s);
        const double phi = 2 * std::numbers::pi * xi;
        worst = std::max({worst, std::abs(c - std::cos(phi)), std::abs(s - std::sin(phi))});
    }
    // A few units of the last place of 1 (2.2e-16 each); the library's own phi is rounded too.
    EXPECT_LT(worst, 2e-15);
}

TEST(Rng, StreamsAreDeterministicAndDistinct) {
    Rng a(7, 1, 2), b(7, 1, 2), c(7, 2, 1), d(8, 1, 2);
    const auto x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    EXPECT_NE(x, c.next_u64());
    EXPECT_NE(x, d.next_u64());
    std::vector<double> u(kSamples);
    for (double& v : u) v = a.uniform();
    const Estimate e = estimate_mean(u);
    EXPECT_TRUE(within_standard_errors("mean of uniform", e.mean, 0.5, e.standard_error));
}

}  // namespace
}  // namespace hmcr::test
