// SPDX-License-Identifier: Apache-2.0
// Mean and standard error over a study's seeds (sample standard deviation / sqrt(n)), and how
// a table prints them: "mean ± se", "mean" for one seed, "–" for none.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>
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

// `format` is a fmt format for one number, such as "{:.2f}".
inline std::string format_mean_se(const MeanSe& m, const std::string& format) {
    if (m.n == 0) return "–";
    const std::string mean = fmt::format(fmt::runtime(format), m.mean);
    if (m.n < 2 || !std::isfinite(m.se)) return mean;
    return mean + " ± " + fmt::format(fmt::runtime(format), m.se);
}

}  // namespace hmcr
