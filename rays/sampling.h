// SPDX-License-Identifier: Apache-2.0
// Samplers; each comment states the density the tests check it against.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
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

// cos and sin of a quarter turn's Taylor series at |theta| <= pi/4, to theta^18 and theta^17:
// the first term left out is below 1e-19.
inline constexpr std::array<double, 10> kTurnCos = {1.0,
                                                    -1.0 / 2,
                                                    1.0 / 24,
                                                    -1.0 / 720,
                                                    1.0 / 40320,
                                                    -1.0 / 3628800,
                                                    1.0 / 479001600,
                                                    -1.0 / 87178291200.0,
                                                    1.0 / 20922789888000.0,
                                                    -1.0 / 6402373705728000.0};
inline constexpr std::array<double, 9> kTurnSin = {1.0,
                                                   -1.0 / 6,
                                                   1.0 / 120,
                                                   -1.0 / 5040,
                                                   1.0 / 362880,
                                                   -1.0 / 39916800,
                                                   1.0 / 6227020800.0,
                                                   -1.0 / 1307674368000.0,
                                                   1.0 / 355687428096000.0};
inline constexpr double kQuarterTurn = 1.5707963267948966;  // pi / 2
inline constexpr double kHalfRoot2 = 0.70710678118654752;   // cos(pi / 4)

// c[0] + x2 (c[1] + x2 (c[2] + ...)).
template <std::size_t N>
double horner(double x2, const std::array<double, N>& c) {
    double r = c[N - 1];
    for (std::size_t k = N - 1; k-- > 0;) r = r * x2 + c[k];
    return r;
}

// cos and sin of 2 pi xi, xi in [0, 1), without a library call (the vector ray generator
// computes them the same way, lane by lane): the quarter turn floor(4 xi), and within it an
// angle at most pi/4 from its middle, whose series converge fast. Accurate to a few units in
// the last place of a double.
inline void cos_sin_turn(double xi, double& cos_out, double& sin_out) {
    const double four_xi = xi * 4.0;
    const double quarter = std::floor(four_xi);
    const double theta = ((four_xi - quarter) - 0.5) * kQuarterTurn;
    const double t2 = theta * theta;
    const double c = horner(t2, kTurnCos), s = theta * horner(t2, kTurnSin);
    const double c1 = (c - s) * kHalfRoot2, s1 = (s + c) * kHalfRoot2;  // at pi/4 + theta
    const auto q = std::int64_t(quarter);
    // A quarter turn maps (c, s) to (-s, c): odd quarters swap, the upper half negates.
    const double cq = (q & 1) ? -s1 : c1, sq = (q & 1) ? c1 : s1;
    cos_out = q >= 2 ? -cq : cq;
    sin_out = q >= 2 ? -sq : sq;
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
