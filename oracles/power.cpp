// SPDX-License-Identifier: Apache-2.0
// power: the classic power-based refinement criterion.
// Hanrahan, Salzman, Aupperle, "A rapid hierarchical radiosity algorithm", SIGGRAPH 1991.
//
//   value = w_ij * A_i * F~_ij,  F~_ij = f * c_i * c_j,  f = A_j / (pi d^2 + A_j),
//   c = max(cos theta, 2 f)  (cos theta = 0 when the element faces away, so c = 2 f there:
//   the centre line facing away says nothing about the elements' other parts)
//
// F~ is a cheap unoccluded estimate of the element-to-element form factor from the centres:
// the disc approximation f, with the cosines bounded below so that near elements, whose
// centre-line cosines say little, still refine.
#include <memory>
#include <numbers>

#include "oracles/oracle.h"

namespace hmcr {
namespace {

class PowerOracle final : public NamedOracle {
public:
    PowerOracle()
        : NamedOracle(
              "power",
              "power transported through the link, unoccluded centre estimate (Hanrahan 1991)",
              1e-5, false) {}

    double geometric_factor(const LinkGeometry& g) const override {
        const double d2 = g.centre_distance * g.centre_distance;
        const double f = g.source_area / (std::numbers::pi * d2 + g.source_area);
        const double ci = std::max(g.receiver_cos, 2 * f);
        const double cj = std::max(g.source_cos, 2 * f);
        return g.receiver_area * f * ci * cj;
    }
};

}  // namespace

std::unique_ptr<Oracle> make_power_oracle() { return std::make_unique<PowerOracle>(); }

}  // namespace hmcr
