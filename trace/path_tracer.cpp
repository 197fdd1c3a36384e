// SPDX-License-Identifier: Apache-2.0
#include "trace/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "trace/bsdf.h"

namespace hmcr {
namespace {

constexpr double kPi = std::numbers::pi;

double power_heuristic(double pdf, double other) { return pdf * pdf / (pdf * pdf + other * other); }

// The hit point put back onto its patch's plane: Embree's float distance leaves it up to ~1e-7
// of the path length off, and a point on the wrong side of the surface would let a grazing
// bounce hit its own patch from the other side.
Vec3 on_plane(const Patch& p, const Vec3& x) {
    return x - p.normal * p.normal.dot(x - p.corner[0]);
}

}  // namespace

struct PathTracer::Vertex {
    Vec3 point;
    std::uint32_t patch = 0;
    std::uint8_t side = kFront;  // the side the path arrived on
    Vec3 wo;                     // unit, back along the path that arrived
};

std::optional<PathTracer::SideHit> PathTracer::side_met(std::uint32_t patch,
                                                        const Vec3& direction) const {
    const double cos_front = -m_set.patches[patch].normal.dot(direction);
    if (cos_front > 0) return SideHit{kFront, cos_front};
    if (cos_front < 0 && m_set.two_sided(patch)) return SideHit{kBack, -cos_front};
    return std::nullopt;  // the back of a one-sided patch, or grazing
}

std::string estimator_name(Estimator e) {
    switch (e) {
        case Estimator::nee:
            return "nee";
        case Estimator::bsdf:
            return "bsdf";
        default:
            return "mis";
    }
}

Estimator parse_estimator(const std::string& name) {
    for (Estimator e : {Estimator::mis, Estimator::nee, Estimator::bsdf}) {
        if (estimator_name(e) == name) return e;
    }
    throw std::invalid_argument("estimator must be mis, nee or bsdf, got '" + name + "'");
}

std::string PathOptions::to_string() const {
    return "PathOptions{max_depth=" + std::to_string(max_depth) +
           ", roulette_depth=" + std::to_string(roulette_depth) +
           ", estimator=" + estimator_name(estimator) + "}";
}

PathTracer::PathTracer(const PatchSet& patches, const PathOptions& options)
    : m_set(patches), m_scene(m_set.patches), m_lights(m_set), m_options(options) {
    if (options.max_depth < 0 || options.roulette_depth < 1) {
        throw std::invalid_argument("bad path options: " + options.to_string());
    }
}

Rgb PathTracer::emitted(std::uint32_t patch, std::uint8_t side) const {
    return m_set.material(patch, side).emission / kPi;
}

CameraSample PathTracer::trace(const Vec3& origin, const Vec3& direction, Rng& rng) const {
    CameraSample s;
    s.rays = 1;
    const auto hit = m_scene.first_hit(origin, direction);
    if (!hit) return s;
    const Patch& p = m_set.patches[hit->patch];
    const auto eye = side_met(hit->patch, direction);
    if (!eye) return s;  // the back of a one-sided patch: black
    s.geometry = eye->cos / (hit->distance * hit->distance);
    const Vertex v{on_plane(p, origin + hit->distance * direction), hit->patch, eye->side,
                   -direction};
    s.radiance = emitted(hit->patch, eye->side) + radiance(v, rng, s.rays);
    return s;
}

Rgb PathTracer::reflected_radiosity(const Vec3& point, std::uint32_t patch, std::uint8_t side,
                                    Rng& rng, std::uint32_t& rays) const {
    // A Lambertian surface reflects the same radiance in every direction: any wo in front of
    // the side will do, and its normal is one.
    const Vertex v{point, patch, side, side_normal(m_set.patches[patch], side)};
    return kPi * radiance(v, rng, rays);
}

// The reflected radiance leaving v towards the previous vertex, one path's estimate.
Rgb PathTracer::radiance(Vertex v, Rng& rng, std::uint32_t& rays) const {
    Rgb sum = Rgb::Zero(), beta = Rgb::Ones();
    for (int bounce = 1; bounce <= m_options.max_depth; ++bounce) {
        const Bsdf bsdf(m_set.material(v.patch, v.side),
                        side_normal(m_set.patches[v.patch], v.side), v.wo);
        if (bsdf.black()) break;
        if (m_options.estimator != Estimator::bsdf && bsdf.has_smooth_lobe()) {
            Vec3 w = Vec3::Zero();
            const Rgb light = next_event(v, bsdf, rng, rays, w);
            sum += beta * bsdf.pi_f(w) * light;
        }
        const auto s = bsdf.sample(rng);
        if (!s) break;
        const Vec3& wi = s->wi;
        beta *= s->weight;
        ++rays;
        const auto hit = m_scene.first_hit(v.point, wi);
        if (!hit) break;
        const auto met = side_met(hit->patch, wi);
        if (!met) break;  // the back of a one-sided patch absorbs
        const double pdf_light =
            m_lights.pdf_area(hit->patch, met->side) * hit->distance * hit->distance / met->cos;
        const Rgb le = emitted(hit->patch, met->side);
        // Through a mirror the emitter counts whole: next-event estimation cannot find it.
        if (s->delta || m_options.estimator == Estimator::bsdf || pdf_light == 0) {
            sum += beta * le;
        } else if (m_options.estimator == Estimator::mis) {
            sum += beta * le * power_heuristic(s->pdf, pdf_light);
        }
        v = {on_plane(m_set.patches[hit->patch], v.point + hit->distance * wi), hit->patch,
             met->side, -wi};
        if (bounce >= m_options.roulette_depth) {
            const double survive = std::min(1.0, beta.maxCoeff());
            if (rng.uniform() >= survive) break;
            beta /= survive;
        }
    }
    return sum;
}

// Next-event estimate of the irradiance at v from the emitters, divided by pi, along the
// direction w it sampled: the caller's pi f(wo, w) times it is the directly reflected radiance.
Rgb PathTracer::next_event(const Vertex& v, const Bsdf& bsdf, Rng& rng, std::uint32_t& rays,
                           Vec3& w) const {
    const double xi = rng.uniform(), xi1 = rng.uniform(), xi2 = rng.uniform();
    const EmitterPoint e = m_lights.sample(m_set.patches, xi, xi1, xi2);
    const Vec3 d = e.point - v.point;
    const double r2 = d.squaredNorm();
    if (!(r2 > 0)) return Rgb::Zero();
    w = d / std::sqrt(r2);
    const double cos_x = side_normal(m_set.patches[v.patch], v.side).dot(w);
    const double cos_y = -side_normal(m_set.patches[e.patch], e.side).dot(w);
    if (cos_x <= 0 || cos_y <= 0) return Rgb::Zero();
    ++rays;
    if (!m_scene.visible(v.point, e.point)) return Rgb::Zero();
    const double weight = m_options.estimator == Estimator::mis
                              ? power_heuristic(e.pdf_area * r2 / cos_y, bsdf.pdf(w))
                              : 1.0;
    return emitted(e.patch, e.side) * (weight * cos_x * cos_y / (r2 * kPi * e.pdf_area));
}

}  // namespace hmcr
