// SPDX-License-Identifier: Apache-2.0
#include "rays/ray_strata.h"

#include <algorithm>
#include <cmath>

#include "common/populated.h"

namespace hmcr {

void RayStrata::assign(std::span<const double> weights, std::uint64_t rays, double offset,
                       std::uint64_t first) {
    m_first = first;
    m_continued = false;
    resize_populated(m_start, weights.size() + 1);
    // The total is summed in the order of the cumulative sums, so that the last is exactly 1.
    double total = 0;
    for (const double w : weights) total += w;
    const double n = double(rays);
    double cumulative = 0;
    for (std::size_t l = 0; l < weights.size(); ++l) {
        // Monotone in the cumulative weight, so no source's count is negative; the first source
        // starts at `first`, as floor(offset) is 0.
        const auto k = std::min(rays, std::uint64_t(std::floor(n * (cumulative / total) + offset)));
        m_start[l] = first + k;
        cumulative += weights[l];
    }
    m_start[weights.size()] = first + rays;
}

void RayStrata::continue_sequences(std::uint64_t key) {
    m_continued = true;
    m_key = key;
    m_sequence.assign(sources(), 0);
    m_first_point.assign(sources(), 0);
}

std::uint32_t RayStrata::source_of(std::uint64_t ray) const {
    // The last source starting at or before the ray: sources with no rays start where the next
    // one does, and are passed over.
    const auto next = std::upper_bound(m_start.begin(), m_start.end() - 1, ray);
    return std::uint32_t(next - m_start.begin() - 1);
}

}  // namespace hmcr
