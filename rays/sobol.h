// SPDX-License-Identifier: Apache-2.0
// Randomised quasi-random draws for the rays leaving the sources (docs/design.md §3.2): the
// rays of an iteration are dealt to their sources (rays/ray_strata.h), and each source's rays
// are the points 0, 1, 2, ... of its own Sobol sequence in the four dimensions of a ray's start
// (the point's u and v, the direction's r and phi), Owen-scrambled in each dimension by a hash
// keyed (seed, key, source, dimension), so that two seeds are independent estimates and each
// is unbiased; on a fixed mesh a source's sequence goes on through the iterations instead
// (RayStrata::continue_sequences). A ray's draws are a function of its index alone, whatever
// batch or thread makes it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace hmcr {

class RayStrata;

// Where a ray's uniforms come from: its keyed pseudo-random stream (rays/rng.h), its source
// picked by an alias table; or its source's scrambled Sobol sequence, the rays dealt to the
// sources.
enum class RaySequence { random, sobol };

// A ray's draws, in the order rays/ray_generator.h takes them: region, u, v, r, phi, dither.
inline constexpr std::size_t kRayDraws = 6;
inline constexpr std::size_t kSequenceDimensions = 4;  // u, v, r, phi; the dither stays random

// The draws of rays first .. first + n - 1 of the stream (seed, key), which `strata` deals to
// their sources: draw d of ray first + i at out[d * stride + i], and its source at source[i].
// Ray r of source l is point strata.first_point(l) + r - strata.first_ray(l) of its sequence
// s = strata.sequence(l) (l + strata.first(), from point 0, unless the strata continue the
// sources' sequences), dimension d scrambled by the hash keyed (seed, strata.scramble_key(key),
// 2^63 + 2^32 + 4 s + d). Each dimension takes its first 32 binary digits from the scrambled
// sequence and the next 21 from the ray's keyed stream (a full Owen scramble makes those
// uniform and independent); draw 0 (an alias pick's) is 0, and the dither is the stream's last
// uniform. This is the one-ray reference; the vector ray generator finishes sobol_digits' output
// the same way in lanes.
void sobol_draws(std::uint64_t seed, std::uint64_t key, const RayStrata& strata,
                 std::uint64_t first, std::size_t n, double* out, std::size_t stride,
                 std::uint32_t* source);

// The part of sobol_draws that walks the sequences: dimension d of ray first + i's point, its
// 32 digits unscrambled, at digits[d * stride + i], that dimension's scramble at
// scrambles[d * stride + i], and the ray's source at source[i]; d < kSequenceDimensions.
void sobol_digits(std::uint64_t seed, std::uint64_t key, const RayStrata& strata,
                  std::uint64_t first, std::size_t n, std::uint32_t* digits,
                  std::uint32_t* scrambles, std::size_t stride, std::uint32_t* source);

// Owen's nested uniform scramble of the 32-digit fraction x, by a hash (Burley, "Practical
// Hash-based Owen Scrambling", JCGT 2020, after Laine and Karras): digit k is flipped by a
// function of `seed` and the digits above it alone.
// On the reversed digits x += seed, then x ^= x * c for each c of kOwenMultipliers.
std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed);
inline constexpr std::uint32_t kOwenMultipliers[] = {0x6c50b47cu, 0xb82f1e52u, 0xc7afe638u,
                                                     0x8d22f6e6u};

}  // namespace hmcr
