#include "rays/sobol.h"

#include <boost/random/sobol.hpp>

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
constexpr std::uint64_t kScrambleStream = std::uint64_t(1) << 63;

}  // namespace

std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    // On the reversed digits, each step changes a digit by the digits below it alone: multiplying
    // by an even constant carries upward only.
    x = reverse_bits(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse_bits(x);
}

void sobol_draws(std::uint64_t seed, std::uint64_t key, std::uint64_t first, std::size_t n,
                 double* out, std::size_t stride) {
    std::uint32_t scramble[kSequenceDimensions];
    for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
        scramble[d] = std::uint32_t(Rng(seed, key, kScrambleStream + d).next_u64() >> 32);
    }
    // Boost's engine (Joe and Kuo's direction numbers) runs in Gray-code order from the
    // sequence's second point: its state after seed(i - 1) is point i (point 0 is all zeros),
    // so that the first 2^m rays are the net they should be. Seeding costs a few XORs a digit of
    // the index, each next point one XOR a dimension.
    boost::random::sobol engine(kSequenceDimensions);
    if (first > 0) engine.seed(first - 1);
    for (std::size_t i = 0; i < n; ++i) {
        const bool origin = first + i == 0;
        Rng rng(seed, key, first + i);
        for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
            const auto digits = origin ? std::uint32_t(0) : std::uint32_t(engine() >> 32);
            const std::uint64_t high = owen_scramble(digits, scramble[d]);
            const std::uint64_t low = rng.next_u64() >> 43;
            out[d * stride + i] = double((high << 21) | low) * 0x1.0p-53;
        }
        out[(kRayDraws - 1) * stride + i] = rng.uniform();
    }
}

}  // namespace hmcr
