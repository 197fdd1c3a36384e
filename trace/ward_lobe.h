// SPDX-License-Identifier: Apache-2.0
// The glossy lobe of MGF's specular reflectance `rs rho_s alpha`: a Gaussian distribution of
// facet slopes of RMS slope alpha (the MGF specification's "Converting between Phong specular
// power and Gaussian roughness"), the isotropic model of its author (Ward, "Measuring and
// modeling anisotropic reflection", SIGGRAPH 1992, eq. 5a with alpha_x = alpha_y):
//
//   f(wo, wi) = rho_s exp(-tan^2(theta_h) / alpha^2) / (4 pi alpha^2 sqrt(cos theta_i cos theta_o))
//
// theta_h the angle between the normal and the half vector h = (wo + wi) / |wo + wi|, both
// directions pointing away from the surface. Sampled through the half vector as Walter corrects
// Ward's weights ("Notes on the Ward BRDF", Cornell PCG-05-06, 2005):
//
//   tan^2(theta_h) = -alpha^2 ln(1 - xi1),  phi_h = 2 pi xi2,  wi = 2 (wo . h) h - wo,
//   p(wi) = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^3(theta_h)) / (4 wo . h)
//
// per steradian: the half vector's density, exact, times the Jacobian of the reflection. A half
// vector that sends wi below the surface gives no direction: that share of the samples is lost,
// which the density accounts for (it integrates to less than 1 over the hemisphere).
#pragma once

#include <optional>

#include "common/types.h"

namespace hmcr {

// f / rho_s for unit directions wo, wi about the unit normal n; 0 unless both are in front.
double ward_lobe(const Vec3& n, const Vec3& wo, const Vec3& wi, double alpha);

// The density of sample_ward_lobe giving wi, per steradian; 0 unless wo and wi are in front.
double ward_lobe_pdf(const Vec3& n, const Vec3& wo, const Vec3& wi, double alpha);

// A direction from two uniforms in [0, 1); none when the sampled half vector reflects wo below
// the surface.
std::optional<Vec3> sample_ward_lobe(const Vec3& n, const Vec3& wo, double alpha, double xi1,
                                     double xi2);

}  // namespace hmcr
