#include "radiosity/kernel.h"

#include <Eigen/Geometry>
#include <array>
#include <numbers>

#include "radiosity/sampling.h"

namespace hmcr {

double point_kernel(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny) {
    const Vec3 d = y - x;
    const double r2 = d.squaredNorm();
    const double cx = nx.dot(d), cy = -ny.dot(d);
    if (cx <= 0 || cy <= 0 || r2 == 0) return 0;
    return cx * cy / (std::numbers::pi * r2 * r2);  // the two cosines carry a factor r each
}

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

void sample_kernel(const EmbreeScene& scene, const Hierarchy& hierarchy, const Element& i,
                   const Element& j, Rng& rng, std::span<double> out) {
    const Patch& pi = hierarchy.patch(i);
    const Patch& pj = hierarchy.patch(j);
    const ElementSampler on_i(pi, i.domain), on_j(pj, j.domain);
    constexpr std::size_t kBatch = 64;
    std::array<Vec3, kBatch> xs, ys;
    std::array<std::size_t, kBatch> slot;
    std::array<bool, kBatch> vis;
    for (std::size_t first = 0; first < out.size(); first += kBatch) {
        const std::size_t n = std::min(kBatch, out.size() - first);
        std::size_t cast = 0;  // only lines with a non-zero kernel need a visibility query
        for (std::size_t k = 0; k < n; ++k) {
            const Vec3 x = pi.point(on_i(rng.uniform(), rng.uniform()));
            const Vec3 y = pj.point(on_j(rng.uniform(), rng.uniform()));
            out[first + k] = point_kernel(x, pi.normal, y, pj.normal);
            if (out[first + k] > 0) {
                xs[cast] = x;
                ys[cast] = y;
                slot[cast++] = first + k;
            }
        }
        scene.visible_many({xs.data(), cast}, {ys.data(), cast}, {vis.data(), cast});
        for (std::size_t k = 0; k < cast; ++k) {
            if (!vis[k]) out[slot[k]] = 0;
        }
    }
}

}  // namespace hmcr
