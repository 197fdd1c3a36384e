// SPDX-License-Identifier: Apache-2.0
#include "radiosity/ray_schedule.h"

#include <algorithm>
#include <cmath>

namespace hmcr {

RaySchedule::RaySchedule(std::uint64_t total_rays, double stop_power)
    : m_total(total_rays), m_stop_power(stop_power) {}

std::uint64_t RaySchedule::next(double unshot, double ratio) const {
    const double left = double(remaining());
    if (left <= 0 || unshot <= 0) return 0;
    const double r = std::clamp(ratio, 1e-6, 0.999);
    // Iterations until the unshot power drops below the stop threshold, this one included;
    // kept fractional, so that a last iteration that just crosses the threshold gets nearly
    // all the rays left instead of saving them for one that will not come.
    const double m = std::max(1.0, std::log(m_stop_power / unshot) / std::log(r));
    const double share = (1 - r) / (1 - std::pow(r, m));  // U_k / predicted sum
    // At least a few rays, so that an iteration past the prediction still moves on.
    return std::max<std::uint64_t>(std::min<std::uint64_t>(64, m_total / 1000 + 1),
                                   std::uint64_t(std::llround(left * share)));
}

}  // namespace hmcr
