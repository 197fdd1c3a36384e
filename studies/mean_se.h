// SPDX-License-Identifier: Apache-2.0
// Mean and standard error over a study's seeds (sample standard deviation / sqrt(n)); how a
// table prints them is studies/summary_table.h's.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace hmcr {

struct MeanSe {
    double mean = std::numeric_limits<double>::quiet_NaN();
    double se = std::numeric_limits<double>::quiet_NaN();
    std::size_t n = 0;
};

inline MeanSe mean_se(const std::vector<double>& v) {
    MeanSe m;
    m.n = v.size();
    if (v.empty()) return m;
    double sum = 0;
    for (double x : v) sum += x;
    m.mean = sum / double(v.size());
    if (v.size() < 2 || !std::isfinite(m.mean)) return m;
    double ss = 0;
    for (double x : v) ss += (x - m.mean) * (x - m.mean);
    m.se = std::sqrt(ss / double(v.size() - 1)) / std::sqrt(double(v.size()));
    return m;
}

}  // namespace hmcr
