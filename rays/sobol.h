// Randomised quasi-random draws for the rays leaving the sources (docs/design.md §3.1): the
// Sobol sequence in the five dimensions of a ray's start (the region, the point's u and v, the
// direction's r and phi), Owen-scrambled in each dimension by a hash keyed (seed, key,
// dimension), so that two seeds are independent estimates and each is unbiased. Ray i of the
// stream (seed, key) is the sequence's point i, whatever batch or thread makes it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace hmcr {

// Where a ray's uniforms come from: its keyed pseudo-random stream (rays/rng.h), or the
// scrambled Sobol sequence of its stream.
enum class RaySequence { random, sobol };

// A ray's draws, in the order rays/ray_generator.h takes them: region, u, v, r, phi, dither.
inline constexpr std::size_t kRayDraws = 6;
inline constexpr std::size_t kSequenceDimensions = 5;  // the dither stays pseudo-random

// The draws of rays first .. first + n - 1 of the stream (seed, key): draw d of ray first + i at
// out[d * stride + i]. Each of the five sequence dimensions takes its first 32 binary digits
// from the scrambled sequence and the next 21 from the ray's keyed stream (a full Owen scramble
// makes those uniform and independent); the dither is the stream's next uniform.
void sobol_draws(std::uint64_t seed, std::uint64_t key, std::uint64_t first, std::size_t n,
                 double* out, std::size_t stride);

// Owen's nested uniform scramble of the 32-digit fraction x, by a hash (Burley, "Practical
// Hash-based Owen Scrambling", JCGT 2020, after Laine and Karras): digit k is flipped by a
// function of `seed` and the digits above it alone.
std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed);

}  // namespace hmcr
