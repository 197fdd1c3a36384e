// SPDX-License-Identifier: Apache-2.0
// ks: kernel smoothness.
// Gortler, Schroeder, Cohen, Hanrahan, "Wavelet radiosity", SIGGRAPH 1993.
//
//   value = w_ij * A_j * max(F_max - F_avg, F_avg - F_min)
//
// The largest deviation of the sampled point-to-point kernel from its mean: a link is refined
// where the kernel, and so the transported radiosity, is not close to constant over the pair.
#include <memory>

#include "oracles/kernel_stats.h"
#include "oracles/oracle.h"

namespace hmcr {
namespace {

class KernelSmoothnessOracle final : public NamedOracle {
public:
    KernelSmoothnessOracle()
        : NamedOracle("ks",
                      "kernel smoothness: largest deviation of the sampled kernel from its mean "
                      "(Gortler 1993)",
                      1.5e-2, true) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const KernelStats s = kernel_stats(g.kernel);
        if (s.sum <= 0) return 0;
        const double avg = s.average();
        return g.source_area * std::max(s.max - avg, avg - s.min);
    }
};

}  // namespace

std::unique_ptr<Oracle> make_ks_oracle() { return std::make_unique<KernelSmoothnessOracle>(); }

}  // namespace hmcr
