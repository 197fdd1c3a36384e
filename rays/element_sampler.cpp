// SPDX-License-Identifier: Apache-2.0
#include "rays/element_sampler.h"

#include "rays/sampling.h"

namespace hmcr {

ElementSampler::ElementSampler(const Patch& patch, const Domain& domain)
    : m_domain(domain),
      m_map(!patch.is_quad()           ? Map::triangle
            : patch.is_parallelogram() ? Map::parallelogram
                                       : Map::bilinear) {
    if (m_map != Map::bilinear) return;
    // The Jacobian of a planar bilinear map is affine in (u, v), so area-uniform sampling is a
    // linear density in s followed by a linear density in t given s.
    const auto c = domain.corners(true);
    m_j00 = patch.jacobian(c[0]);
    m_j10 = patch.jacobian(c[1]);
    m_j11 = patch.jacobian(c[2]);
    m_j01 = patch.jacobian(c[3]);
}

Vec2 ElementSampler::operator()(double xi1, double xi2) const {
    const Domain& d = m_domain;
    switch (m_map) {
        case Map::triangle: {
            const Vec2 ab = sample_uniform_triangle(xi1, xi2);
            return {d.u0 + d.s * ab.x(), d.v0 + d.s * ab.y()};
        }
        case Map::parallelogram:  // constant Jacobian: uniform in parameter space
            return {d.u0 + d.s * xi1, d.v0 + d.s * xi2};
        case Map::bilinear:
            break;
    }
    const double s = sample_linear(m_j00 + m_j01, m_j10 + m_j11, xi1);
    const double t = sample_linear((1 - s) * m_j00 + s * m_j10, (1 - s) * m_j01 + s * m_j11, xi2);
    return {d.u0 + d.s * s, d.v0 + d.s * t};
}

Vec2 sample_element(const Patch& patch, const Domain& domain, double xi1, double xi2) {
    return ElementSampler(patch, domain)(xi1, xi2);
}

}  // namespace hmcr
