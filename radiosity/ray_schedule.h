// How many rays each iteration shoots (SPEC section 3, step 8): proportional to its unshot
// power, so that the whole solve shoots the requested total.
//
// The unshot power of stochastic Jacobi falls roughly geometrically with ratio r (an average
// reflectance). Before iteration k we predict the unshot power of the iterations still to come,
// U_k (1 + r + ... + r^(m-1)) with m the iterations until U falls below the stop threshold, and
// give iteration k its share U_k / (that sum) of the rays still unspent. r starts at the area-
// weighted mean reflectance and is then the measured ratio of the last iteration.
#pragma once

#include <cstdint>

namespace hmcr {

class RaySchedule {
public:
    RaySchedule(std::uint64_t total_rays, double stop_power, double initial_ratio);

    // Rays for the next iteration, whose unshot power is `unshot`.
    std::uint64_t next(double unshot) const;
    // Records what an iteration shot and the unshot power before and after it.
    void record(std::uint64_t rays, double unshot_before, double unshot_after);
    std::uint64_t remaining() const { return m_total > m_spent ? m_total - m_spent : 0; }

private:
    std::uint64_t m_total;
    std::uint64_t m_spent = 0;
    double m_stop_power;
    double m_ratio;
};

}  // namespace hmcr
