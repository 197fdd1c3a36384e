// SPDX-License-Identifier: Apache-2.0
// cc: classic contrast of a pixel's luminances, weighted by their mean.
// Mitchell, "Generating antialiased images at low sampling densities", SIGGRAPH 1987 (eq. 6 of
// Rigau, Feixas, Sbert, EGSR 2003), weighted by the mean as in Glassner 1995, p. 476, and as
// the CC of that paper's Table 1:
//
//   value = L-bar (L_max - L_min) / (L_max + L_min)
//
// over all the pixel's samples so far. Unlike the divergences it does not fall as samples are
// added (the range only widens), so a pixel either stops after its first batch or goes on to its
// maximum. When to use it: a cheap edge detector; Table 1's worst (RMSE 6.16).
#include <algorithm>
#include <memory>

#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

class ClassicContrastCriterion final : public NamedCriterion {
public:
    ClassicContrastCriterion()
        : NamedCriterion("cc",
                         "L-bar (L_max - L_min) / (L_max + L_min), classic contrast "
                         "(Mitchell 1987)",
                         Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        const Luminances l = luminances(samples);
        const auto [lo, hi] = std::minmax_element(l.values.begin(), l.values.end());
        if (lo == l.values.end() || !(*hi + *lo > 0)) return 0;
        return l.mean() * (*hi - *lo) / (*hi + *lo);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_cc_criterion() {
    return std::make_unique<ClassicContrastCriterion>();
}

}  // namespace hmcr
