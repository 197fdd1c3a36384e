// SPDX-License-Identifier: Apache-2.0
#include "trace/ward_lobe.h"

#include <cmath>
#include <numbers>

#include "rays/sampling.h"

namespace hmcr {
namespace {

constexpr double kPi = std::numbers::pi;

// exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^3(theta_h)): the half vector's density, for
// cos_h = n . h > 0.
double half_vector_pdf(double cos_h, double alpha) {
    const double cos2 = cos_h * cos_h, tan2 = (1 - cos2) / cos2;
    return std::exp(-tan2 / (alpha * alpha)) / (kPi * alpha * alpha * cos2 * cos_h);
}

}  // namespace

double ward_lobe(const Vec3& n, const Vec3& wo, const Vec3& wi, double alpha) {
    const double cos_o = n.dot(wo), cos_i = n.dot(wi);
    if (!(cos_o > 0 && cos_i > 0)) return 0;
    const double cos_h = n.dot((wo + wi).normalized());
    const double cos2 = cos_h * cos_h, tan2 = (1 - cos2) / cos2;
    return std::exp(-tan2 / (alpha * alpha)) / (4 * kPi * alpha * alpha * std::sqrt(cos_i * cos_o));
}

double ward_lobe_pdf(const Vec3& n, const Vec3& wo, const Vec3& wi, double alpha) {
    if (!(n.dot(wo) > 0 && n.dot(wi) > 0)) return 0;
    const Vec3 h = (wo + wi).normalized();
    return half_vector_pdf(n.dot(h), alpha) / (4 * wo.dot(h));
}

std::optional<Vec3> sample_ward_lobe(const Vec3& n, const Vec3& wo, double alpha, double xi1,
                                     double xi2) {
    const double tan2 = -alpha * alpha * std::log1p(-xi1);
    const double cos_h = 1 / std::sqrt(1 + tan2), sin_h = std::sqrt(tan2) * cos_h;
    const double phi = 2 * kPi * xi2;
    Vec3 t, b;
    tangent_frame(n, t, b);
    const Vec3 h = sin_h * std::cos(phi) * t + sin_h * std::sin(phi) * b + cos_h * n;
    const double cos_oh = wo.dot(h);
    if (!(cos_oh > 0)) return std::nullopt;
    const Vec3 wi = (2 * cos_oh * h - wo).normalized();
    if (!(n.dot(wi) > 0)) return std::nullopt;
    return wi;
}

}  // namespace hmcr
