// SPDX-License-Identifier: Apache-2.0
#include "radiosity/truncation.h"

#include <limits>

namespace hmcr {

Rgb reflected_power(const Hierarchy& h) {
    Rgb sum = Rgb::Zero();
    const PatchSet& set = h.patch_set();
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        sum += h.root(p).area * (h.root(p).radiosity - set.material(p, kFront).emission);
        if (const Element* back = h.back_root(p)) {
            sum += back->area * (back->radiosity - set.material(p, kBack).emission);
        }
    }
    return sum;
}

TruncationBias truncation_bias(const Solution& solution) {
    TruncationBias t;
    t.unshot = solution.stats.unshot_power;
    t.reflected = reflected_power(*solution.hierarchy);
    const auto& its = solution.stats.iterations;
    if (its.empty()) return t;
    const IterationRecord& last = its.back();
    for (int c = 0; c < 3; ++c) {
        const double before = last.unshot_before[c], after = last.unshot_after[c];
        // A closed white scene (r = 1) never converges: its tail is unbounded.
        t.decay[c] = before > 0 ? after / before : 0;
        t.missing[c] = t.decay[c] < 1 ? t.unshot[c] * t.decay[c] / (1 - t.decay[c])
                                      : std::numeric_limits<double>::infinity();
        t.relative[c] = t.reflected[c] > 0 ? t.missing[c] / t.reflected[c] : 0;
    }
    return t;
}

}  // namespace hmcr
