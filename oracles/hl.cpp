// SPDX-License-Identifier: Apache-2.0
// hl: squared Hellinger distance of the sampled kernel from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003.
//
//   value = w_ij * A_i A_j F^ * h2(p||q),  h2 = 1/2 sum_k (sqrt(p_k) - sqrt(1/N_s))^2
//
// h2 is in [0, 1]: a bounded, symmetric divergence, the least sensitive to single spikes.
#include <memory>

#include "oracles/divergences.h"
#include "oracles/kernel_stats.h"
#include "oracles/oracle.h"

namespace hmcr {
namespace {

class HellingerOracle final : public NamedOracle {
public:
    HellingerOracle()
        : NamedOracle("hl",
                      "squared Hellinger distance of the sampled kernel from uniform (Rigau 2003)",
                      4e-6, true) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const KernelStats s = kernel_stats(g.kernel);
        if (s.sum <= 0) return 0;
        // h2 = 0.5 * sum: halving is exact, so this is the value hl always gave.
        return g.receiver_area * g.source_area * s.sum * hellinger_divergence(g.kernel, s.sum);
    }
};

}  // namespace

std::unique_ptr<Oracle> make_hl_oracle() { return std::make_unique<HellingerOracle>(); }

}  // namespace hmcr
