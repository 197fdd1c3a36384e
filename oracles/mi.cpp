// SPDX-License-Identifier: Apache-2.0
// mi: mutual-information discretisation error.
// Feixas, Rigau, Bekaert, Sbert, "Information-theoretic oracle based on kernel smoothness for
// hierarchical radiosity", Eurographics 2002 (short presentations).
//
//   value = w_ij * (A_i A_j / A_T) * [ (1/N_s) sum_k F_k ln F_k - F_avg ln F_avg ]
//
// The bracket is Jensen's gap of f(x) = x ln x over the sampled kernel: the mutual information
// the discretisation of the pair loses (docs/design.md §4). mi = kl / (A_T N_s) exactly.
#include <memory>

#include "oracles/kernel_stats.h"
#include "oracles/oracle.h"

namespace hmcr {
namespace {

class MutualInformationOracle final : public NamedOracle {
public:
    MutualInformationOracle()
        : NamedOracle("mi",
                      "mutual information lost by the discretisation, Jensen gap of x ln x "
                      "(Feixas 2002)",
                      6e-7, true) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const KernelStats s = kernel_stats(g.kernel);
        if (s.sum <= 0) return 0;
        double mean_x_log_x = 0;
        for (double f : g.kernel) mean_x_log_x += x_log_x(f);
        mean_x_log_x /= s.n;
        const double gap = std::max(0.0, mean_x_log_x - x_log_x(s.average()));
        return g.receiver_area * g.source_area / g.total_area * gap;
    }
};

}  // namespace

std::unique_ptr<Oracle> make_mi_oracle() { return std::make_unique<MutualInformationOracle>(); }

}  // namespace hmcr
