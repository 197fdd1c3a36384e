// SPDX-License-Identifier: Apache-2.0
// Keyed random streams (docs/design.md §3): every ray and every oracle pair draws from a stream
// determined by its keys alone, so results do not depend on thread scheduling.
// The generator is SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014): a Weyl sequence passed through a 64-bit finaliser.
#pragma once

#include <cstdint>

namespace hmcr {

class Rng {
public:
    Rng(std::uint64_t seed, std::uint64_t key_a, std::uint64_t key_b = 0)
        : m_state(mix(mix(mix(seed + kGamma) ^ (key_a + 2 * kGamma)) ^ (key_b + 3 * kGamma))) {}

    std::uint64_t next_u64() { return mix(m_state += kGamma); }
    // Uniform in [0, 1), 53 random bits.
    double uniform() { return double(next_u64() >> 11) * 0x1.0p-53; }

private:
    static constexpr std::uint64_t kGamma = 0x9e3779b97f4a7c15ULL;
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    std::uint64_t m_state;
};

}  // namespace hmcr
