#include "radiosity/ray_schedule.h"

#include <algorithm>
#include <cmath>

namespace hmcr {

RaySchedule::RaySchedule(std::uint64_t total_rays, double stop_power, double initial_ratio)
    : m_total(total_rays), m_stop_power(stop_power),
      m_ratio(std::clamp(initial_ratio, 0.01, 0.99)) {}

std::uint64_t RaySchedule::next(double unshot) const {
    const double left = double(remaining());
    if (left <= 0 || unshot <= 0) return 0;
    // Iterations until the unshot power drops below the stop threshold, this one included;
    // kept fractional, so that a last iteration that just crosses the threshold gets nearly
    // all the rays left instead of saving them for one that will not come.
    const double m = std::max(1.0, std::log(m_stop_power / unshot) / std::log(m_ratio));
    const double share = (1 - m_ratio) / (1 - std::pow(m_ratio, m));  // U_k / predicted sum
    // At least a few rays, so that an iteration past the prediction still moves on.
    return std::max<std::uint64_t>(std::min<std::uint64_t>(64, m_total / 1000 + 1),
                                   std::uint64_t(std::llround(left * share)));
}

void RaySchedule::record(std::uint64_t rays, double unshot_before, double unshot_after) {
    m_spent += rays;
    if (unshot_before > 0 && unshot_after > 0) {
        m_ratio = std::clamp(unshot_after / unshot_before, 0.01, 0.99);
    }
}

}  // namespace hmcr
