// SPDX-License-Identifier: Apache-2.0
// vt: variance of the normalised sampled kernel.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003 (the variance
// criterion it compares the f-divergences with).
//
//   value = w_ij * A_i A_j F^2 * V(p),  V = (1/N_s) sum_k p_k^2 - 1/N_s^2,  p_k = F_k / F^
//
// A_i A_j F^2 V is, up to constants, the variance of the kernel samples themselves.
#include <cmath>
#include <memory>

#include "oracles/kernel_stats.h"
#include "oracles/oracle.h"

namespace hmcr {
namespace {

class VarianceOracle final : public NamedOracle {
public:
    VarianceOracle()
        : NamedOracle("vt", "variance of the normalised sampled kernel (Rigau 2003)", 4.5e-4,
                      true) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const KernelStats s = kernel_stats(g.kernel);
        if (s.sum <= 0) return 0;
        double sum_p2 = 0;
        for (double f : g.kernel) sum_p2 += (f / s.sum) * (f / s.sum);
        const double v = std::max(0.0, sum_p2 / s.n - 1 / (s.n * s.n));
        return g.receiver_area * g.source_area * s.sum * s.sum * v;
    }
};

}  // namespace

std::unique_ptr<Oracle> make_vt_oracle() { return std::make_unique<VarianceOracle>(); }

}  // namespace hmcr
