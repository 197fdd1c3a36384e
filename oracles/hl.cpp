// hl: squared Hellinger distance of the sampled kernel from the uniform distribution.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003.
//
//   value = w_ij * A_i A_j F^ * h2(p||q),  h2 = 1/2 sum_k (sqrt(p_k) - sqrt(1/N_s))^2
//
// h2 is in [0, 1]: a bounded, symmetric divergence, the least sensitive to single spikes.
#include <cmath>
#include <memory>

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
        const double sq = std::sqrt(1 / s.n);
        double h2 = 0;
        for (double f : g.kernel) h2 += (std::sqrt(f / s.sum) - sq) * (std::sqrt(f / s.sum) - sq);
        return g.receiver_area * g.source_area * s.sum * 0.5 * h2;
    }
};

}  // namespace

std::unique_ptr<Oracle> make_hl_oracle() { return std::make_unique<HellingerOracle>(); }

}  // namespace hmcr
