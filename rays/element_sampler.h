// SPDX-License-Identifier: Apache-2.0
// Points uniformly distributed by area on an element of a patch (density 1 / A_element), in the
// patch's parameter space: where a ray starts, where a kernel line ends, where a light is
// sampled. What depends on the element alone is computed once, for the many points a line
// sampler draws on it.
#pragma once

#include <cstdint>

#include "rays/domain.h"
#include "rays/patch.h"

namespace hmcr {

class ElementSampler {
public:
    ElementSampler(const Patch& patch, const Domain& domain);
    Vec2 operator()(double xi1, double xi2) const;

private:
    const Domain m_domain;
    enum class Map : std::uint8_t { triangle, parallelogram, bilinear } m_map;
    double m_j00 = 0, m_j10 = 0, m_j11 = 0, m_j01 = 0;  // bilinear: the Jacobian at the corners
};

// One point, as ElementSampler(patch, domain)(xi1, xi2).
Vec2 sample_element(const Patch& patch, const Domain& domain, double xi1, double xi2);

}  // namespace hmcr
