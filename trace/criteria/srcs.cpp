// SPDX-License-Identifier: Apache-2.0
// srcs: square root of the chi-square divergence of a pixel's luminances from uniform.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003, section 4.
//
//   value = L-bar sqrt(chi2(p, q)) / n  (eq. 28),   p_i = L_i / sum L_i,  q_i = 1/n
//   chi2(p, q) = n sum (p_i - 1/n)^2 (eq. 15)
//
// n counts the pixel's samples so far: dividing by it makes the refinement stop (the paper's
// remark on eq. 25); L-bar, the mean luminance, weighs the divergence by how bright the pixel
// is. The divergence is the one the refinement oracles use (oracles/divergences.h). When to use
// it: sqrt(chi2) is the coefficient of variation of the luminances up to a factor; Table 1:
// RMSE 4.77.
#include <memory>

#include "oracles/divergences.h"
#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

class RootChiSquareCriterion final : public NamedCriterion {
public:
    RootChiSquareCriterion()
        : NamedCriterion("srcs", "L-bar sqrt(chi2(p, q)) / n, root of chi-square (Rigau 2003)",
                         Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        return divergence_value(samples, chi_square_divergence, true);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_srcs_criterion() {
    return std::make_unique<RootChiSquareCriterion>();
}

}  // namespace hmcr
