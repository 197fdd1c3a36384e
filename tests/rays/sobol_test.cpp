// The scrambled Sobol draws (rays/sobol.h): a function of the ray's index alone, a (0, m, 2)-net
// in their first two dimensions and stratified in each (the properties Owen's scramble keeps),
// uniform over seeds, and independent of the batch that makes them.
#include "rays/sobol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/statistics.h"

namespace hmcr::test {
namespace {

std::vector<double> draws(std::uint64_t seed, std::uint64_t key, std::uint64_t first,
                          std::size_t n) {
    std::vector<double> out(kRayDraws * n);
    sobol_draws(seed, key, first, n, out.data(), n);
    return out;
}

TEST(Sobol, ARaysDrawsDoNotDependOnItsBatch) {
    const std::vector<double> whole = draws(3, 4, 0, 300);
    for (std::uint64_t first : {0u, 1u, 127u, 255u}) {
        const std::vector<double> part = draws(3, 4, first, 300 - first);
        for (std::size_t d = 0; d < kRayDraws; ++d) {
            for (std::size_t i = 0; i + first < 300; ++i) {
                ASSERT_EQ(part[d * (300 - first) + i], whole[d * 300 + first + i])
                    << "draw " << d << " of ray " << first + i;
            }
        }
    }
}

// The first 2^m points: one in each interval of length 2^-m in every sequence dimension, and in
// the first two dimensions one in each box 2^-a x 2^-(m - a).
TEST(Sobol, TheFirstPowerOfTwoPointsAreStratified) {
    constexpr int m = 10;
    constexpr std::size_t n = std::size_t(1) << m;
    for (std::uint64_t seed : {1u, 2u, 99u}) {
        const std::vector<double> x = draws(seed, 7, 0, n);
        for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
            std::vector<int> count(n);
            for (std::size_t i = 0; i < n; ++i) ++count[std::size_t(x[d * n + i] * double(n))];
            for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(count[k], 1) << "dimension " << d;
        }
        for (int a = 0; a <= m; ++a) {
            std::vector<int> count(n);
            for (std::size_t i = 0; i < n; ++i) {
                const auto u = std::size_t(std::ldexp(x[i], a));
                const auto v = std::size_t(std::ldexp(x[n + i], m - a));
                ++count[(u << (m - a)) + v];
            }
            for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(count[k], 1) << "box 2^-" << a;
        }
    }
}

// Over seeds, one ray's draw is uniform: its mean 1/2 within its standard error
// sqrt(1 / 12 / seeds), for every draw and for rays at both ends of a dyadic block.
TEST(Sobol, EachDrawIsUniformOverSeeds) {
    constexpr int kSeeds = 4000;
    for (std::uint64_t index : {0u, 1u, 1023u}) {
        for (std::size_t d = 0; d < kRayDraws; ++d) {
            double sum = 0;
            for (int s = 0; s < kSeeds; ++s) sum += draws(std::uint64_t(s), 5, index, 1)[d];
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
