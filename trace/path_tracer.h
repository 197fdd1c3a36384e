// SPDX-License-Identifier: Apache-2.0
// A path tracer of the radiosity engine's scenes: the same patches through the same
// Embree facade, so that a traced image is an independent solution of the same light transport.
//
// Surfaces reflect diffusely with reflectance rho, plus a mirror or a glossy lobe where the
// material has specular reflectance (trace/bsdf.h); an emitter has radiance Le = E / pi (E its
// emitted radiosity, pi Ke). A path that meets a patch takes the side it meets, as the radiosity
// engine does (docs/design.md §1.3, §10.1): the front, or the back of a two-sided patch, with that
// side's material, reflecting into that side's hemisphere (around the reversed normal on a back,
// a mirror's included). The back of a one-sided patch is black and absorbs.
//
// The estimator of the radiance along a camera ray (Veach 1997, ch. 9; pbrt's path integrator):
//   - next-event estimation: at every bounce on a surface with a diffuse or glossy lobe one
//     point y on the emitting sides (trace/emitter_sampler.h) and a shadow ray, contributing
//     f cos_x cos_y Le / (r^2 p_A(y));
//   - BSDF sampling: a continuation drawn by trace/bsdf.h (cosine-distributed on a diffuse
//     surface), throughput times f cos / p (rho on a diffuse surface);
//   - both kinds of path to an emitter weighed by the power heuristic (beta = 2) of their two
//     densities in solid angle, p_bsdf (cos_x / pi on a diffuse surface) and
//     p_light = p_A(y) r^2 / cos_y; a mirror's reflection has no density, and an emitter seen
//     through it counts with weight 1 (next-event estimation cannot sample it);
//   - Russian roulette from bounce `roulette_depth` on: continue with probability
//     q = min(1, max channel of the throughput) and divide the throughput by q, which keeps the
//     estimator unbiased;
//   - at most `max_depth` bounces: paths with more reflections are cut, a bias below
//     max_rho^(max_depth + 1) / (1 - max_rho) times the largest Le (2.6e-20 for the furnace).
// Estimator::nee and Estimator::bsdf keep one of the two strategies alone (weight 1), for tests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rays/embree_scene.h"
#include "rays/patch.h"
#include "rays/rng.h"
#include "trace/emitter_sampler.h"

namespace hmcr {

class Bsdf;

enum class Estimator { mis, nee, bsdf };

struct PathOptions {
    int max_depth = 64;                    // bounces after the camera hit, >= 0
    int roulette_depth = 3;                // Russian roulette from this bounce on, >= 1
    Estimator estimator = Estimator::mis;  // how paths to emitters are found

    std::string to_string() const;
};

// "mis", "nee", "bsdf"; parse_estimator throws std::invalid_argument on anything else.
std::string estimator_name(Estimator e);
Estimator parse_estimator(const std::string& name);

// One camera ray's result: what the pixel sampling criteria see.
struct CameraSample {
    Rgb radiance = Rgb::Zero();  // W sr^-1 m^-2
    double geometry = 0;         // |cos(theta)| / d^2 at the first hit (0 on a black back)
    std::uint32_t rays = 0;      // Embree queries cast, shadow rays included
};

class PathTracer {
public:
    // Throws std::invalid_argument on bad options or a scene where nothing emits.
    PathTracer(const PatchSet& patches, const PathOptions& options);

    // The caller's thread should have set_tracing_float_mode() (rays/embree_scene.h).
    CameraSample trace(const Vec3& origin, const Vec3& direction, Rng& rng) const;

    // One path's estimate of the radiance a diffuse surface point reflects, times pi: the
    // reflected radiosity B - E at `point` (on the plane of `patch`, on its `side`), for a
    // surface whose material is diffuse (the radiosity engine's view). Its expectation is
    // rho / pi times the integral of the incoming radiance L_in cos over the side's hemisphere,
    // times pi; the same estimator as a camera path's from its first hit on.
    Rgb reflected_radiosity(const Vec3& point, std::uint32_t patch, std::uint8_t side, Rng& rng,
                            std::uint32_t& rays) const;

    const PathOptions& options() const { return m_options; }
    const PatchSet& patches() const { return m_set; }

private:
    struct Vertex;  // a surface point a path reflects at
    struct SideHit {
        std::uint8_t side = kFront;
        double cos = 0;  // between the side's normal and the reversed direction, > 0
    };
    // The side a ray along `direction` meets, or none: the back of a one-sided patch, or grazing.
    std::optional<SideHit> side_met(std::uint32_t patch, const Vec3& direction) const;
    Rgb emitted(std::uint32_t patch, std::uint8_t side) const;  // Le = E / pi of the side
    Rgb next_event(const Vertex& v, const Bsdf& bsdf, Rng& rng, std::uint32_t& rays, Vec3& w) const;
    Rgb radiance(Vertex v, Rng& rng, std::uint32_t& rays) const;

    PatchSet m_set;
    EmbreeScene m_scene;
    EmitterSampler m_lights;
    PathOptions m_options;
};

}  // namespace hmcr
