// The point-to-point form factor kernel and the line sampler of SPEC section 4.
#pragma once

#include <span>

#include "radiosity/embree_scene.h"
#include "radiosity/hierarchy.h"
#include "radiosity/rng.h"

namespace hmcr {

// max(0, cos theta_x) max(0, cos theta_y) / (pi r^2), without visibility.
double point_kernel(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny);

// A point uniformly distributed by area on an element (density 1 / A_element).
Vec2 sample_element(const Patch& patch, const Domain& domain, double xi1, double xi2);

// Fills out[k] = F(x_k, y_k) for out.size() lines, x_k uniform on element i, y_k uniform on
// element j, visibility from Embree (one coherent packet per 16 lines).
void sample_kernel(const EmbreeScene& scene, const Hierarchy& hierarchy, const Element& i,
                   const Element& j, Rng& rng, std::span<double> out);

}  // namespace hmcr
