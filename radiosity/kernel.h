// The point-to-point form factor kernel and the line sampler of SPEC section 4.
#pragma once

#include <cstdint>
#include <span>

#include "radiosity/embree_scene.h"
#include "radiosity/hierarchy.h"
#include "radiosity/rng.h"

namespace hmcr {

// max(0, cos theta_x) max(0, cos theta_y) / (pi r^2), without visibility.
double point_kernel(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny);

// Points uniformly distributed by area on an element (density 1 / A_element). What depends on
// the element alone is computed once, for the many points the line sampler draws on it.
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

// Fills out[k] = F(x_k, y_k) for out.size() lines, x_k uniform on element i, y_k uniform on
// element j, visibility from Embree (one coherent packet per 16 lines).
void sample_kernel(const EmbreeScene& scene, const Hierarchy& hierarchy, const Element& i,
                   const Element& j, Rng& rng, std::span<double> out);

}  // namespace hmcr
