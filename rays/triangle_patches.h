// SPDX-License-Identifier: Apache-2.0
// The patch of each triangle of a patch scene. A quad's two triangles are consecutive, so the
// patch of triangle t is t less the quads' second triangles up to it: one bit per triangle and
// one count per 64 triangles, 0.4 MB at 10^6 patches where a patch number per triangle took
// 8 MB at the solve's peak memory (and a cache miss per hit).
#pragma once

#include <cstdint>
#include <vector>

namespace hmcr {

class TrianglePatches {
public:
    void reserve(std::size_t triangles) {
        m_bits.reserve(triangles / 64 + 1);
        m_before.reserve(triangles / 64 + 1);
    }
    // The next triangle: the first of its patch, or a quad's second.
    void push(bool second_of_quad) {
        if (m_count % 64 == 0) {
            m_bits.push_back(0);
            m_before.push_back(m_seconds);
        }
        if (second_of_quad) {
            m_bits.back() |= std::uint64_t(1) << (m_count % 64);
            ++m_seconds;
        }
        ++m_count;
    }
    std::uint32_t size() const { return m_count; }
    // Whether triangle t is the second triangle of a quad.
    bool second_of_quad(std::uint32_t t) const { return (m_bits[t / 64] >> (t % 64)) & 1; }
    std::uint32_t operator[](std::uint32_t t) const {
        // Bits 0 .. t % 64 (all 64 when t % 64 = 63: the shift wraps to 0, minus 1 all ones).
        const std::uint64_t upto = m_bits[t / 64] & ((std::uint64_t(2) << (t % 64)) - 1);
        return t - m_before[t / 64] - ones(upto);
    }

private:
    // std::popcount is a library call on the x86-64 baseline the build targets (no POPCNT):
    // the bit-parallel count inline is a third of the instructions at each hit.
    static std::uint32_t ones(std::uint64_t x) {
        x -= (x >> 1) & 0x5555555555555555u;
        x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
        x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
        return std::uint32_t((x * 0x0101010101010101u) >> 56);
    }

    std::vector<std::uint64_t> m_bits;    // bit t % 64 of word t / 64: a quad's second triangle
    std::vector<std::uint32_t> m_before;  // second triangles in the words before this one
    std::uint32_t m_count = 0, m_seconds = 0;
};

}  // namespace hmcr
