// SPDX-License-Identifier: Apache-2.0
// cs: chi-square divergence of a pixel's luminances from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003, section 4.
//
//   value = L-bar chi2(p, q) / n,   p_i = L_i / sum L_i,  q_i = 1/n
//   chi2(p, q) = n sum (p_i - 1/n)^2 (eq. 15), in [0, n - 1]
//
// n counts the pixel's samples so far: dividing by it makes the refinement stop (the paper's
// remark on eq. 25); L-bar, the mean luminance, weighs the divergence by how bright the pixel
// is. The divergence is the one the refinement oracles use (oracles/divergences.h). When to use
// it: squares the deviations, so a single bright sample (a light seen through a gap) weighs more
// than in kl; Table 1: RMSE 5.41.
#include <memory>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

class ChiSquareCriterion final : public NamedCriterion {
public:
    ChiSquareCriterion()
        : NamedCriterion("cs", "L-bar chi2(p, q) / n, chi-square (Rigau 2003)", Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        return divergence_value(samples, chi_square_divergence, false);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_cs_criterion() { return std::make_unique<ChiSquareCriterion>(); }

}  // namespace hmcr
