// SPDX-License-Identifier: Apache-2.0
// var: the confidence-interval half-width of a pixel's mean luminance.
// Purgathofer, "A statistical method for adaptive stochastic sampling", Eurographics 1986
// (eqs. 7-8 of Rigau, Feixas, Sbert, EGSR 2003): sampling stops when the true luminance L is
// within d of the estimate with probability 1 - alpha,
//
//   value = t_(1 - alpha/2, n - 1) s / sqrt(n)   <= d,   alpha = 0.1 (the paper's)
//
// s the sample standard deviation of the n luminances so far. The threshold plays the paper's d
// (0.025 on its display scale; hmcr's luminance is physical, so d is the threshold the spp
// search finds). Eq. 7 is two-sided, hence the 1 - alpha/2 quantile. When to use it: noise
// rather than edges; Table 1 puts it between the root divergences and CC (RMSE 5.19).
#include <cmath>
#include <memory>

#include "trace/criteria/criterion.h"
#include "trace/criteria/luminances.h"

namespace hmcr {
namespace {

constexpr double kAlpha = 0.1;
constexpr double kZ = 1.6448536269514722;  // the standard normal's 1 - alpha/2 quantile
static_assert(kAlpha == 0.1, "kZ is the quantile for alpha = 0.1: compute it again");

// Student's t quantile at 1 - alpha/2 with nu degrees of freedom: the Cornish-Fisher expansion
// of Abramowitz and Stegun 26.7.5 around kZ, within 2e-5 for nu >= 7 (every batch has n >= 8).
double t_quantile(double nu) {
    const double z = kZ, z2 = z * z;
    const double g1 = (z2 + 1) * z / 4;
    const double g2 = ((5 * z2 + 16) * z2 + 3) * z / 96;
    const double g3 = (((3 * z2 + 19) * z2 + 17) * z2 - 15) * z / 384;
    const double g4 = ((((79 * z2 + 776) * z2 + 1482) * z2 - 1920) * z2 - 945) * z / 92160;
    return z + (g1 + (g2 + (g3 + g4 / nu) / nu) / nu) / nu;
}

class VarianceCriterion final : public NamedCriterion {
public:
    VarianceCriterion()
        : NamedCriterion("var",
                         "t(1 - alpha/2, n - 1) s / sqrt(n), alpha = 0.1: confidence "
                         "half-width (Purgathofer 1986)",
                         Scheme::batches) {}

    double value(std::span<const PixelSample> samples, double) const override {
        const Luminances l = luminances(samples);
        if (l.values.size() < 2) return 0;
        double ss = 0;
        for (double x : l.values) ss += (x - l.mean()) * (x - l.mean());
        const double s = std::sqrt(ss / (l.n() - 1));
        return t_quantile(l.n() - 1) * s / std::sqrt(l.n());
    }
};

}  // namespace

std::unique_ptr<Criterion> make_var_criterion() { return std::make_unique<VarianceCriterion>(); }

}  // namespace hmcr
