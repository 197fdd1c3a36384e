// SPDX-License-Identifier: Apache-2.0
// he: squared Hellinger distance of a pixel's luminances from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003, section 4.
//
//   value = L-bar h2(p, q) / n,   p_i = L_i / sum L_i,  q_i = 1/n
//   h2(p, q) = 1/2 sum (sqrt(p_i) - sqrt(1/n))^2 (eq. 16), in [0, 1)
//
// n counts the pixel's samples so far: dividing by it makes the refinement stop (the paper's
// remark on eq. 25); L-bar, the mean luminance, weighs the divergence by how bright the pixel
// is. The divergence is the one the refinement oracles use (oracles/divergences.h). When to use
// it: bounded and the least sensitive to one spiky sample; Table 1: RMSE 5.81.
#include <memory>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

class HellingerCriterion final : public NamedCriterion {
public:
    HellingerCriterion()
        : NamedCriterion("he", "L-bar h2(p, q) / n, squared Hellinger (Rigau 2003)",
                         Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        return divergence_value(samples, hellinger_divergence, false);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_he_criterion() { return std::make_unique<HellingerCriterion>(); }

}  // namespace hmcr
