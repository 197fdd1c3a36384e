// SPDX-License-Identifier: Apache-2.0
// cs: chi-square divergence of the sampled kernel from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003.
//
//   value = w_ij * A_i A_j F^ * chi2(p||q),  chi2 = N_s sum_k (p_k - 1/N_s)^2,  p_k = F_k / F^
//
// chi2 is in [0, N_s - 1]; it weighs large deviations more than kl does.
#include <memory>

#include "oracles/divergences.h"
#include "oracles/kernel_stats.h"
#include "oracles/oracle.h"

namespace hmcr {
namespace {

class ChiSquareOracle final : public NamedOracle {
public:
    ChiSquareOracle()
        : NamedOracle("cs", "chi-square divergence of the sampled kernel from uniform (Rigau 2003)",
                      2.5e-5, true) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const KernelStats s = kernel_stats(g.kernel);
        if (s.sum <= 0) return 0;
        return g.receiver_area * g.source_area * s.sum * s.n *
               squared_deviation_from_uniform(g.kernel, s.sum);
    }
};

}  // namespace

std::unique_ptr<Oracle> make_cs_oracle() { return std::make_unique<ChiSquareOracle>(); }

}  // namespace hmcr
