// Samplers; each comment states the density the tests check it against.
#pragma once

#include <cmath>
#include <numbers>

#include "common/types.h"

namespace hmcr {

// Density on [0,1] proportional to (1-x) a + x b (a, b >= 0, not both 0).
inline double sample_linear(double a, double b, double xi) {
    if (a == b) return xi;
    // Inverse CDF, rearranged to avoid cancellation when a and b are close.
    return xi * (a + b) / (a + std::sqrt((1 - xi) * a * a + xi * b * b));
}

// Uniform point of the triangle {u, v >= 0, u + v <= 1}; density 2.
inline Vec2 sample_uniform_triangle(double xi1, double xi2) {
    const double r = std::sqrt(xi1);
    return {r * (1 - xi2), r * xi2};
}

// Orthonormal tangent frame around a unit normal (Duff et al. 2017, "Building an
// orthonormal basis, revisited").
inline void tangent_frame(const Vec3& n, Vec3& t, Vec3& b) {
    const double sign = std::copysign(1.0, n.z());
    const double a = -1.0 / (sign + n.z());
    const double c = n.x() * n.y() * a;
    t = Vec3(1 + sign * n.x() * n.x() * a, sign * c, -sign * n.x());
    b = Vec3(c, sign + n.y() * n.y() * a, -n.y());
}

// Cosine-distributed direction around the unit normal n; density cos(theta) / pi per sr.
inline Vec3 sample_cosine_hemisphere(const Vec3& n, double xi1, double xi2) {
    const double r = std::sqrt(xi1), phi = 2 * std::numbers::pi * xi2;
    Vec3 t, b;
    tangent_frame(n, t, b);
    return r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1 - xi1)) * n;
}

// Uniform direction on the unit sphere; density 1 / (4 pi) per sr.
inline Vec3 sample_uniform_sphere(double xi1, double xi2) {
    const double z = 1 - 2 * xi1, r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = 2 * std::numbers::pi * xi2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Uniform point of the unit disk; density 1 / pi.
inline Vec2 sample_uniform_disk(double xi1, double xi2) {
    const double r = std::sqrt(xi1), phi = 2 * std::numbers::pi * xi2;
    return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace hmcr
