// SPDX-License-Identifier: Apache-2.0
// Summary statistics of the N_s kernel samples F_k of a link, shared by the line-based oracles.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace hmcr {

struct KernelStats {
    double sum = 0;  // F^ = sum_k F_k
    double min = std::numeric_limits<double>::infinity();
    double max = 0;
    double n = 0;  // N_s

    double average() const { return sum / n; }  // F_avg
};

inline KernelStats kernel_stats(std::span<const double> f) {
    KernelStats s;
    s.n = double(f.size());
    for (double x : f) {
        s.sum += x;
        s.min = std::min(s.min, x);
        s.max = std::max(s.max, x);
    }
    return s;
}

// x ln x with the limit 0 at 0.
inline double x_log_x(double x) { return x > 0 ? x * std::log(x) : 0.0; }

}  // namespace hmcr
