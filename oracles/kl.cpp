// SPDX-License-Identifier: Apache-2.0
// kl: Kullback-Leibler divergence of the sampled kernel from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003.
//
//   value = w_ij * A_i A_j F^ * D(p||q),  D = sum_k p_k ln(N_s p_k),  p_k = F_k / F^, q = 1/N_s
//
// D is 0 for a constant kernel and at most ln N_s; F^ weighs it by how much the pair exchanges.
// The best of the seven for radiosity in the papers, and the default oracle.
#include <memory>

#include "oracles/divergences.h"
#include "oracles/kernel_stats.h"
#include "oracles/oracle.h"

namespace hmcr {
namespace {

class KullbackLeiblerOracle final : public NamedOracle {
public:
    KullbackLeiblerOracle()
        : NamedOracle("kl",
                      "Kullback-Leibler divergence of the sampled kernel from uniform (Rigau 2003)",
                      1e-5, true) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const KernelStats s = kernel_stats(g.kernel);
        if (s.sum <= 0) return 0;
        return g.receiver_area * g.source_area * s.sum * kl_divergence(g.kernel, s.sum);
    }
};

}  // namespace

std::unique_ptr<Oracle> make_kl_oracle() { return std::make_unique<KullbackLeiblerOracle>(); }

}  // namespace hmcr
