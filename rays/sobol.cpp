// SPDX-License-Identifier: Apache-2.0
#include "rays/sobol.h"

#include <array>
#include <bit>
#include <boost/random/sobol.hpp>
#include <vector>

#include "rays/ray_strata.h"
#include "rays/rng.h"

namespace hmcr {
namespace {

std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

// Outside the rays' indices (below 2^62), so that no ray's stream is a scramble's.
constexpr std::uint64_t kScrambleStreams = (std::uint64_t(1) << 63) + (std::uint64_t(1) << 32);

// The first 32 digits of Boost's Sobol sequence (Joe and Kuo's direction numbers), in its
// Gray-code order: point p is the XOR of the direction numbers v_j of the bits j of
// p ^ (p >> 1). Boost's engine is read once for the v_j (v_j is point 2^(j + 1) - 1, whose
// Gray code is 2^j: its state after seed(2^(j + 1) - 2)); the points are then a few XORs each,
// where the engine's own step costs a call a dimension.
using Directions = std::array<std::array<std::uint32_t, kSequenceDimensions>, 64>;

const Directions& directions() {
    static const Directions v = [] {
        Directions out{};
        boost::random::sobol engine(kSequenceDimensions);
        for (std::size_t j = 0; j < out.size(); ++j) {
            const std::uint64_t point = (std::uint64_t(2) << j) - 1;  // 2^64 - 1 for j = 63
            engine.seed(point - 1);
            for (std::uint32_t& digits : out[j]) digits = std::uint32_t(engine() >> 32);
        }
        return out;
    }();
    return v;
}

using Digits = std::array<std::uint32_t, kSequenceDimensions>;

Digits sobol_point(const Directions& v, std::uint64_t p) {
    Digits out{};
    for (std::uint64_t gray = p ^ (p >> 1); gray != 0; gray &= gray - 1) {
        const Digits& row = v[std::size_t(std::countr_zero(gray))];
        for (std::size_t d = 0; d < kSequenceDimensions; ++d) out[d] ^= row[d];
    }
    return out;
}

// Point p + 1's digits from point p's: their Gray codes differ in bit ctz(p + 1).
void next_point(const Directions& v, std::uint64_t p_plus_1, Digits& digits) {
    const Digits& row = v[std::size_t(std::countr_zero(p_plus_1))];
    for (std::size_t d = 0; d < kSequenceDimensions; ++d) digits[d] ^= row[d];
}

}  // namespace

std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    // On the reversed digits, each step changes a digit by the digits below it alone: multiplying
    // by an even constant carries upward only.
    x = reverse_bits(x);
    x += seed;
    for (const std::uint32_t c : kOwenMultipliers) x ^= x * c;
    return reverse_bits(x);
}

void sobol_digits(std::uint64_t seed, std::uint64_t key, const RayStrata& strata,
                  std::uint64_t first, std::size_t n, std::uint32_t* digits,
                  std::uint32_t* scrambles, std::size_t stride, std::uint32_t* source) {
    std::uint32_t scramble[kSequenceDimensions] = {};
    std::uint32_t current = 0;
    std::uint64_t end = 0;    // of the current source's rays: none yet
    std::uint64_t start = 0;  // ray + start is the ray's point in its source's sequence
    const Directions& v = directions();
    Digits point{};
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t ray = first + i;
        if (ray >= end) {  // a new source: its scrambles, and its sequence from the ray's point
            current = strata.source_of(ray);
            end = strata.first_ray(current + 1);
            const std::uint64_t at = kScrambleStreams + 4 * strata.sequence(current);
            const std::uint64_t scramble_key = strata.scramble_key(key);
            for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
                scramble[d] = std::uint32_t(Rng(seed, scramble_key, at + d).next_u64() >> 32);
            }
            start = strata.first_point(current) - strata.first_ray(current);  // mod 2^64
            point = sobol_point(v, ray + start);
        } else {
            next_point(v, ray + start, point);
        }
        for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
            digits[d * stride + i] = point[d];
            scrambles[d * stride + i] = scramble[d];
        }
        source[i] = current;
    }
}

void sobol_draws(std::uint64_t seed, std::uint64_t key, const RayStrata& strata,
                 std::uint64_t first, std::size_t n, double* out, std::size_t stride,
                 std::uint32_t* source) {
    std::vector<std::uint32_t> digits(kSequenceDimensions * n), scrambles(digits.size());
    sobol_digits(seed, key, strata, first, n, digits.data(), scrambles.data(), n, source);
    for (std::size_t i = 0; i < n; ++i) {
        Rng rng(seed, key, first + i);
        rng.next_u64();  // the alias pick's draw, unused: the others keep their places
        out[i] = 0;
        for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
            const std::uint64_t high = owen_scramble(digits[d * n + i], scrambles[d * n + i]);
            out[(d + 1) * stride + i] = double((high << 21) | (rng.next_u64() >> 43)) * 0x1.0p-53;
        }
        out[(kRayDraws - 1) * stride + i] = rng.uniform();
    }
}

}  // namespace hmcr
