// SPDX-License-Identifier: Apache-2.0
// How many rays each iteration shoots (docs/design.md §3): proportional to its unshot
// power, so that the whole solve shoots the requested total.
//
// The unshot power of stochastic Jacobi falls roughly geometrically with ratio r (an average
// reflectance). Before iteration k we predict the unshot power of the iterations still to come,
// U_k (1 + r + ... + r^(m-1)) with m the iterations until U falls below the stop threshold, and
// give iteration k its share U_k / (that sum) of the rays still unspent. r is the fraction of
// iteration k's power that its receivers will reflect, estimated by a small pilot of rays
// (shooting.h): a guess from past iterations fails where the light dies out early (black
// occluders and emitters: the second iteration can be the last).
#pragma once

#include <cstdint>

namespace hmcr {

class RaySchedule {
public:
    RaySchedule(std::uint64_t total_rays, double stop_power);

    // Rays for the next iteration, whose unshot power is `unshot` and of which a fraction
    // `ratio` is expected to be reflected.
    std::uint64_t next(double unshot, double ratio) const;
    void record(std::uint64_t rays) { m_spent += rays; }
    std::uint64_t remaining() const { return m_total > m_spent ? m_total - m_spent : 0; }

private:
    std::uint64_t m_total;
    std::uint64_t m_spent = 0;
    double m_stop_power;
};

}  // namespace hmcr
