// SPDX-License-Identifier: Apache-2.0
// How a surface point reflects, for the path tracer (docs/design.md §10.1): a Lambertian part of
// reflectance rho_d plus a specular part rho_s, an ideal mirror at roughness 0, else the glossy
// lobe of trace/ward_lobe.h. rho_d + rho_s <= 1 per channel (meshes/validation.h).
//
//   f(wo, wi) = rho_d / pi + rho_s delta(wi - mirror(wo)) / cos(theta_i)   roughness 0
//   f(wo, wi) = rho_d / pi + rho_s ward(wo, wi)                            roughness alpha > 0
//
// sample() picks the specular part with probability P_s = |rho_s| / (|rho_d| + |rho_s|) (|c| the
// channel sum), else the diffuse part, and returns the direction with the weight f cos / p:
//   - a mirror reflection: weight rho_s / P_s, no density (a delta lobe, which next-event
//     estimation cannot sample: an emitter seen through it counts whole);
//   - any other direction: weight f cos / p with p = P_d cos / pi + P_s p_ward (the mixture's
//     density, 0 for the mirror's part), which is also the density multiple importance sampling
//     weighs it with.
// A surface without a specular part takes the cosine-weighted direction with weight rho_d,
// drawing the same uniforms as before hmcr had specular surfaces, so diffuse scenes trace the
// same bits.
#pragma once

#include <optional>

#include "common/types.h"
#include "rays/patch.h"
#include "rays/rng.h"

namespace hmcr {

class Bsdf {
public:
    // wo: the unit direction back along the arriving path, in front of the unit normal n (the
    // normal of the side the path meets: reversed on the back of a two-sided patch).
    Bsdf(const PatchMaterial& material, const Vec3& n, const Vec3& wo);

    bool black() const { return m_black; }
    // A lobe that next-event estimation can sample: diffuse, or glossy.
    bool has_smooth_lobe() const { return m_diffuse_p > 0 || (m_specular_p > 0 && !is_mirror()); }

    // pi f(wo, wi) of the lobes other than a mirror's: what multiplies irradiance / pi. rho_d
    // for a diffuse surface.
    Rgb pi_f(const Vec3& wi) const;
    // The density of sample() giving wi through those lobes, per steradian.
    double pdf(const Vec3& wi) const;

    struct Sample {
        Vec3 wi;
        Rgb weight;          // f cos / p
        double pdf = 0;      // per steradian; 0 for the mirror
        bool delta = false;  // the mirror's reflection
    };
    // None when the glossy lobe reflects below the surface (the path ends).
    std::optional<Sample> sample(Rng& rng) const;

private:
    bool is_mirror() const { return m_roughness == 0; }

    const Rgb& m_diffuse;
    const Rgb& m_specular;
    double m_roughness;
    Vec3 m_n, m_wo;
    double m_diffuse_p = 0, m_specular_p = 0;  // P_d, P_s
    bool m_black = false;
};

}  // namespace hmcr
