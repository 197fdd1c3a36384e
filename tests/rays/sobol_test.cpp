// SPDX-License-Identifier: Apache-2.0
// The scrambled Sobol draws (rays/sobol.h): a function of the ray's index alone, each source's
// rays a (0, m, 2)-net in the point's two dimensions and stratified in each of the four (the
// properties Owen's scramble keeps), uniform over seeds, and independent of the batch that
// makes them.
#include "rays/sobol.h"

#include <gtest/gtest.h>

#include <boost/random/sobol.hpp>
#include <cmath>
#include <vector>

#include "rays/ray_strata.h"
#include "tests/support/statistics.h"

namespace hmcr::test {
namespace {

struct Draws {
    std::vector<double> x;
    std::vector<std::uint32_t> source;
};

Draws draws(std::uint64_t seed, std::uint64_t key, const RayStrata& strata, std::uint64_t first,
            std::size_t n) {
    Draws d{std::vector<double>(kRayDraws * n), std::vector<std::uint32_t>(n)};
    sobol_draws(seed, key, strata, first, n, d.x.data(), n, d.source.data());
    return d;
}

RayStrata one_source(std::uint64_t rays) {
    RayStrata s;
    s.assign(std::vector<double>{1.0}, rays, 0.5);
    return s;
}

TEST(Sobol, ARaysDrawsDoNotDependOnItsBatch) {
    RayStrata strata;
    strata.assign(std::vector<double>{0.3, 0.1, 0, 0.6}, 300, 0.25);
    const Draws whole = draws(3, 4, strata, 0, 300);
    for (std::uint64_t first : {0u, 1u, 29u, 127u, 255u}) {
        const Draws part = draws(3, 4, strata, first, 300 - first);
        for (std::size_t i = 0; i + first < 300; ++i) {
            ASSERT_EQ(part.source[i], whole.source[first + i]) << "ray " << first + i;
            ASSERT_EQ(part.source[i], strata.source_of(first + i)) << "ray " << first + i;
            for (std::size_t d = 0; d < kRayDraws; ++d) {
                ASSERT_EQ(part.x[d * (300 - first) + i], whole.x[d * 300 + first + i])
                    << "draw " << d << " of ray " << first + i;
            }
        }
    }
}

// A source's first 2^m rays, wherever they start among the iteration's: one in each interval
// of length 2^-m in every sequence dimension, and in the point's two dimensions one in each box
// 2^-a x 2^-(m - a).
TEST(Sobol, ASourcesFirstPowerOfTwoPointsAreStratified) {
    constexpr int m = 10;
    constexpr std::size_t n = std::size_t(1) << m;
    RayStrata strata;  // the second source gets exactly 2^m rays, from ray 333 on
    strata.assign(std::vector<double>{333, double(n), 100}, 333 + n + 100, 0.5);
    ASSERT_EQ(strata.first_ray(1), 333u);
    ASSERT_EQ(strata.first_ray(2), 333u + n);
    for (std::uint64_t seed : {1u, 2u, 99u}) {
        const Draws all = draws(seed, 7, strata, 333, n);
        const std::vector<double>& x = all.x;
        for (std::size_t d = 1; d <= kSequenceDimensions; ++d) {
            std::vector<int> count(n);
            for (std::size_t i = 0; i < n; ++i) ++count[std::size_t(x[d * n + i] * double(n))];
            for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(count[k], 1) << "dimension " << d;
        }
        for (int a = 0; a <= m; ++a) {
            std::vector<int> count(n);
            for (std::size_t i = 0; i < n; ++i) {
                const auto u = std::size_t(std::ldexp(x[n + i], a));
                const auto v = std::size_t(std::ldexp(x[2 * n + i], m - a));
                ++count[(u << (m - a)) + v];
            }
            for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(count[k], 1) << "box 2^-" << a;
        }
    }
}

// A source whose sequence continues (RayStrata::continue_sequences) takes the points after its last
// iteration's: two iterations of 2^(m-1) rays each are, together, one net of 2^m points in each
// dimension, though each iteration's rays are keyed streams of their own.
TEST(Sobol, AContinuedSourceGoesOnWhereItsLastRaysStopped) {
    constexpr int m = 10;
    constexpr std::size_t half = std::size_t(1) << (m - 1), n = 2 * half;
    constexpr std::uint64_t kKey = std::uint64_t(1) << 32;
    for (std::uint64_t seed : {1u, 2u, 99u}) {
        std::vector<double> x[2];
        for (std::uint64_t iteration : {0u, 1u}) {
            RayStrata strata;  // the source of interest second, after one of 100 rays
            strata.assign(std::vector<double>{100, double(half)}, 100 + half, 0.5);
            ASSERT_EQ(strata.first_ray(1), 100u);
            strata.continue_sequences(kKey);
            strata.continue_source(0, 7, 0);
            strata.continue_source(1, 3, iteration * half);
            x[iteration] = draws(seed, iteration, strata, 100, half).x;
        }
        for (std::size_t d = 1; d <= kSequenceDimensions; ++d) {
            std::vector<int> count(n);
            for (const std::vector<double>& it : x) {
                for (std::size_t i = 0; i < half; ++i) ++count[std::size_t(it[d * half + i] * n)];
            }
            for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(count[k], 1) << "dimension " << d;
        }
    }
}

// The digits are Boost's Sobol sequence, point p its engine's state after seed(p - 1), from a
// source's first point and from one far along a continued sequence.
TEST(Sobol, TheDigitsAreBoostsSequence) {
    constexpr std::size_t n = 3000;
    for (const std::uint64_t first_point : {std::uint64_t(0), (std::uint64_t(1) << 40) + 3}) {
        RayStrata strata = one_source(n);
        strata.continue_sequences(9);
        strata.continue_source(0, 4, first_point);
        std::vector<std::uint32_t> digits(kSequenceDimensions * n), scrambles(digits.size());
        std::vector<std::uint32_t> source(n);
        sobol_digits(1, 2, strata, 0, n, digits.data(), scrambles.data(), n, source.data());
        boost::random::sobol engine(kSequenceDimensions);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t p = first_point + i;
            if (p > 0) engine.seed(p - 1);
            for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
                const auto expected = p == 0 ? std::uint32_t(0) : std::uint32_t(engine() >> 32);
                ASSERT_EQ(digits[d * n + i], expected) << "point " << p << ", dimension " << d;
                ASSERT_EQ(scrambles[d * n + i], scrambles[d * n]) << "point " << p;
            }
        }
    }
}

// Over seeds, one ray's draw is uniform: its mean 1/2 within its standard error
// sqrt(1 / 12 / seeds), for every draw and for rays at both ends of a dyadic block.
TEST(Sobol, EachDrawIsUniformOverSeeds) {
    constexpr int kSeeds = 4000;
    const RayStrata strata = one_source(2048);
    for (std::uint64_t index : {0u, 1u, 1023u}) {
        for (std::size_t d = 1; d < kRayDraws; ++d) {
            double sum = 0;
            for (int s = 0; s < kSeeds; ++s)
                sum += draws(std::uint64_t(s), 5, strata, index, 1).x[d];
            EXPECT_TRUE(within_standard_errors("mean draw", sum / kSeeds, 0.5,
                                               std::sqrt(1.0 / 12 / kSeeds)))
                << "draw " << d << " of ray " << index;
        }
    }
}

// A nested uniform scramble is a bijection of the 2^k intervals at every depth k: here k = 12.
TEST(Sobol, TheScrambleKeepsEveryDyadicIntervalWhole) {
    constexpr int k = 12;
    std::vector<int> count(std::size_t(1) << k);
    for (std::uint32_t i = 0; i < (1u << k); ++i)
        ++count[owen_scramble(i << (32 - k), 12345) >> (32 - k)];
    for (const int c : count) ASSERT_EQ(c, 1);
}

}  // namespace
}  // namespace hmcr::test
