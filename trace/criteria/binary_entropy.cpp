// SPDX-License-Identifier: Apache-2.0
// binary-entropy: the entropy contrast of a quadtree node from its extreme samples only.
// Rigau, Feixas, Sbert, "Entropy-based adaptive supersampling", 2003, section 2.3 (the binary
// pixel entropy "computed by only considering the maximum and minimum values") and eq. 19.
//
//   C_i = 1 - H_2(p) / ln 2,   p = c_max / (c_max + c_min)
//
// which is D((p, 1 - p) || (1/2, 1/2)) / ln 2, the oracles' Kullback-Leibler divergence
// (oracles/divergences.h) of the two-point distribution. Combined into eq. 19 by
// trace/criteria/entropy_contrast.h. When to use it: like `entropy`, a little cheaper, and blind
// to how the samples between the extremes are spread.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/entropy_contrast.h"

namespace hmcr {
namespace {

double binary_entropy_contrast(std::span<const double> values, double) {
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    const std::array<double, 2> extremes = {*hi, *lo};
    return kl_divergence(extremes, *hi + *lo) / std::numbers::ln2;
}

class BinaryEntropyCriterion final : public NamedCriterion {
public:
    BinaryEntropyCriterion()
        : NamedCriterion("binary-entropy",
                         "entropy contrast of each node's extreme samples on "
                         "a subpixel quadtree (Rigau 2003)",
                         Scheme::quadtree) {}

    double value(std::span<const PixelSample> samples, double area) const override {
        return entropy_contrast(samples, area, binary_entropy_contrast);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_binary_entropy_criterion() {
    return std::make_unique<BinaryEntropyCriterion>();
}

}  // namespace hmcr
