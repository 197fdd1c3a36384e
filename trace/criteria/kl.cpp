// SPDX-License-Identifier: Apache-2.0
// kl: Kullback-Leibler divergence of a pixel's luminances from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003, section 4.
//
//   value = L-bar D(p||q) / n,   p_i = L_i / sum L_i,  q_i = 1/n
//   D(p||q) = sum p_i ln(n p_i) (eq. 14), in [0, ln n]
//
// n counts the pixel's samples so far: dividing by it makes the refinement stop (the paper's
// remark on eq. 25); L-bar, the mean luminance, weighs the divergence by how bright the pixel
// is. The divergence is the one the refinement oracles use (oracles/divergences.h). When to use
// it: the paper's own KL criterion (eq. 25): refines noisy and edge pixels in proportion to their
// brightness; its Table 1 puts it between VAR and CC (RMSE 5.51).
#include <memory>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

class KullbackLeiblerCriterion final : public NamedCriterion {
public:
    KullbackLeiblerCriterion()
        : NamedCriterion("kl", "L-bar D(p||q) / n, Kullback-Leibler (Rigau 2003)",
                         Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        return divergence_value(samples, kl_divergence, false);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_kl_criterion() {
    return std::make_unique<KullbackLeiblerCriterion>();
}

}  // namespace hmcr
