// SPDX-License-Identifier: Apache-2.0
// srhe: Hellinger distance h of a pixel's luminances from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003, section 4.
//
//   value = L-bar sqrt(h2(p, q)) / n  (eq. 29),   p_i = L_i / sum L_i,  q_i = 1/n
//   h2(p, q) = 1/2 sum (sqrt(p_i) - sqrt(1/n))^2 (eq. 16); h = sqrt(h2) is a metric
//
// n counts the pixel's samples so far: dividing by it makes the refinement stop (the paper's
// remark on eq. 25); L-bar, the mean luminance, weighs the divergence by how bright the pixel
// is. The divergence is the one the refinement oracles use (oracles/divergences.h). When to use
// it: the paper's winner (Table 1: RMSE 4.60), which it puts down to h being a true metric.
#include <memory>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

class RootHellingerCriterion final : public NamedCriterion {
public:
    RootHellingerCriterion()
        : NamedCriterion("srhe", "L-bar h(p, q) / n, the Hellinger distance (Rigau 2003)",
                         Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        return divergence_value(samples, hellinger_divergence, true);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_srhe_criterion() {
    return std::make_unique<RootHellingerCriterion>();
}

}  // namespace hmcr
