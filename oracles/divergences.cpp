// SPDX-License-Identifier: Apache-2.0
#include "oracles/divergences.h"

#include <algorithm>
#include <cmath>

namespace hmcr {

double kl_divergence(std::span<const double> w, double sum) {
    const double n = double(w.size());
    double d = 0;
    for (double x : w) {
        const double p = x / sum;
        if (p > 0) d += p * std::log(n * p);  // 0 ln 0 = 0
    }
    return std::max(0.0, d);  // rounding can leave a uniform distribution a hair below 0
}

double squared_deviation_from_uniform(std::span<const double> w, double sum) {
    const double q = 1 / double(w.size());
    double s = 0;
    for (double x : w) s += (x / sum - q) * (x / sum - q);
    return s;
}

double hellinger_divergence(std::span<const double> w, double sum) {
    const double sq = std::sqrt(1 / double(w.size()));
    double h = 0;
    for (double x : w) h += (std::sqrt(x / sum) - sq) * (std::sqrt(x / sum) - sq);
    return 0.5 * h;
}

}  // namespace hmcr
