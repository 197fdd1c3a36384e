// SPDX-License-Identifier: Apache-2.0
#include "trace/bsdf.h"

#include <numbers>

#include "rays/sampling.h"
#include "trace/ward_lobe.h"

namespace hmcr {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

Bsdf::Bsdf(const PatchMaterial& material, const Vec3& n, const Vec3& wo)
    : m_diffuse(material.reflectance),
      m_specular(material.specular),
      m_roughness(material.roughness),
      m_n(n),
      m_wo(wo) {
    const double d = (m_diffuse > 0).any() ? channel_sum(m_diffuse) : 0;
    const double s = (m_specular > 0).any() ? channel_sum(m_specular) : 0;
    m_black = !(d + s > 0);
    if (m_black) return;
    m_diffuse_p = s > 0 ? d / (d + s) : 1;
    m_specular_p = s > 0 ? 1 - m_diffuse_p : 0;
}

Rgb Bsdf::pi_f(const Vec3& wi) const {
    if (m_specular_p == 0 || is_mirror()) return m_diffuse;
    return m_diffuse + m_specular * (kPi * ward_lobe(m_n, m_wo, wi, m_roughness));
}

double Bsdf::pdf(const Vec3& wi) const {
    if (m_specular_p == 0) return m_n.dot(wi) / kPi;
    const double diffuse = m_diffuse_p > 0 ? m_diffuse_p * std::max(0.0, m_n.dot(wi)) / kPi : 0;
    if (is_mirror()) return diffuse;
    return diffuse + m_specular_p * ward_lobe_pdf(m_n, m_wo, wi, m_roughness);
}

std::optional<Bsdf::Sample> Bsdf::sample(Rng& rng) const {
    const bool specular = m_specular_p > 0 && (m_diffuse_p == 0 || rng.uniform() < m_specular_p);
    if (specular && is_mirror()) {
        const Vec3 wi = 2 * m_n.dot(m_wo) * m_n - m_wo;
        return Sample{wi, m_specular / m_specular_p, 0, true};
    }
    const double xi1 = rng.uniform(), xi2 = rng.uniform();
    if (m_specular_p == 0) {  // diffuse alone: f cos / p = rho_d
        const Vec3 wi = sample_cosine_hemisphere(m_n, xi1, xi2);
        return Sample{wi, m_diffuse, pdf(wi), false};
    }
    Vec3 wi;
    if (specular) {
        const auto glossy = sample_ward_lobe(m_n, m_wo, m_roughness, xi1, xi2);
        if (!glossy) return std::nullopt;
        wi = *glossy;
    } else {
        wi = sample_cosine_hemisphere(m_n, xi1, xi2);
    }
    const double p = pdf(wi), cos_i = m_n.dot(wi);
    if (!(p > 0 && cos_i > 0)) return std::nullopt;
    return Sample{wi, pi_f(wi) * (cos_i / (kPi * p)), p, false};
}

}  // namespace hmcr
