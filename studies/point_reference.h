// SPDX-License-Identifier: Apache-2.0
// Point references (docs/design.md §6.9): the radiosity of a scene at fixed stratified points on
// every surface side (rays/surface_points.h), each estimated by the path tracer, independent of
// any mesh; and every view path-traced, for the image metrics. Every surface is diffuse, as the
// radiosity engine sees it (a specular part is absorbed, docs/design.md §1.2), so a point
// reference is an independent solution of the radiosity engine's own light transport.
//
// Each point's B = E + (B - E) is estimated twice, with seeds s and s + 1, each from `paths`
// paths (trace/path_tracer.h, reflected_radiosity: next-event estimation and multiple importance
// sampling from the point on), each with the variance of its mean. Both are kept: the object
// error against the reference subtracts the reference's own variance from the squared error
// (studies/point_error.h), and the two seeds check the variances (their difference, less its
// expected square, is zero within its standard error).
//
// On disk (`hmcr reference SCENE --points N -o DIR`):
//   DIR/points.vtp        the points and both seeds' estimates (viz/point_radiosity_file.h)
//   DIR/reference.json    {"command", "hmcr_version", "reference": {"kind": "points", "scene",
//                         "points", "paths", "seeds", "path", "report", "views", "seconds"}}
//   DIR/views/VIEW.pfm    each view traced by the same diffuse path tracer, linear radiance
//   DIR/views/VIEW.png    the same, 8-bit sRGB at the view's exposure
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/progress.h"
#include "common/ranks.h"
#include "meshes/scene.h"
#include "studies/traced_reference.h"
#include "trace/path_tracer.h"
#include "trace/trace_image.h"
#include "viz/point_radiosity_file.h"

namespace hmcr {

// The defaults, chosen by measurement (docs/decisions.md, "Point references").
inline constexpr std::uint64_t kDefaultReferencePoints = 400'000;
inline constexpr std::uint64_t kDefaultPathsPerPoint = 64;
inline constexpr double kDefaultReferenceViewSpp = 64;
// Above this noise (relative to the reflected radiosity, as an object error) `hmcr reference`
// warns: a cell's object error near or below it is measured only through the noise's removal,
// with a standard error of the noise's own size, and the removal leans on the paths' variance
// estimates, which heavy-tailed paths make unsure. kTargetNoise is what its advice aims for.
inline constexpr double kNoiseWarning = 0.1;
inline constexpr double kTargetNoise = 0.05;

// The paths a point that bring `noise` (measured with `paths`) to kTargetNoise: the noise
// falls as one over the root of the paths.
std::uint64_t paths_for_target_noise(double noise, std::uint64_t paths);

struct PointReferenceOptions {
    std::uint64_t points = kDefaultReferencePoints;  // the target: strata of A_T / points m^2
    std::uint64_t paths = kDefaultPathsPerPoint;     // per point and seed, >= 2
    std::uint64_t seed = 1;                          // the first; the second is seed + 1
    std::uint64_t strata_seed = 0;                   // another jitter of the same strata
    int threads = 0;                                 // 0: every core; the result is the same
    PathOptions path;
    // The views: every view traced uniformly at views.spp (views.seed the same seed).
    TraceOptions views = [] {
        TraceOptions t;
        t.spp = kDefaultReferenceViewSpp;
        return t;
    }();
};

// What a point reference says of itself, each relative to the reflected radiosity as an object
// error is (sqrt of area-weighted squares over the area-weighted |B - E|^2).
struct PointReferenceReport {
    // The standard error of the two seeds' mean, in object-error terms: its own noise.
    double noise = 0;
    // The seeds' squared difference less its expected value (the sum of their variances), over
    // the reflected radiosity's square: zero in expectation when the variances are right;
    // `seed_check_se` its standard error.
    double seed_check = 0, seed_check_se = 0;
    // The points' spacing: A_T / points, m^2 (a leaf smaller than this holds less than one
    // point on average).
    double area_per_point = 0;
    std::uint64_t rays = 0;  // cast by the points' paths, both seeds
};

struct PointReference {
    PointRadiosity points;
    PointReferenceReport report;
    std::map<std::string, TracedView> views;
    double seconds = 0;
};

// The path tracer's scene: the scene's patches, every specular part absorbed.
PatchSet diffuse_patch_set(const Scene& scene);

// Throws InputError on options no point reference can be made with, or when the points would
// need more memory than the machine holds; called before any work.
void validate_point_reference(const Scene& scene, const PointReferenceOptions& options);

// Estimates the points, the report and every view's image; the points are shared among `ranks`
// (each rank estimates a block, every rank ends with all, the same bits for any count).
PointReference compute_point_reference(const Scene& scene, const PointReferenceOptions& options,
                                       Progress& progress = no_progress(),
                                       const Ranks& ranks = Ranks::single());

// The points alone, estimated as compute_point_reference estimates them (o's points,
// strata_seed, paths and seed; a mesh reference's check of its own discretisation takes a few);
// `rays` gets the rays their paths cast.
PointRadiosity estimate_reference_points(const Scene& scene, const PathTracer& tracer,
                                         const PointReferenceOptions& o, Progress& progress,
                                         const Ranks& ranks, std::uint64_t& rays);

// The report of a reference's points (compute_point_reference fills it; a reader recomputes it).
PointReferenceReport point_report(const PointRadiosity& r, const std::vector<Rgb>& emission);

// The emitted radiosity E of each point's side.
std::vector<Rgb> point_emission(const PatchSet& set, const std::vector<SurfacePoint>& points);

std::vector<std::filesystem::path> point_reference_files(const std::filesystem::path& dir,
                                                         const Scene& scene);

// Writes the folder described above into `out`, an OutputSet of point_reference_files(dir,
// scene), which the caller commits.
void write_point_reference(OutputSet& out, const std::filesystem::path& dir, const Scene& scene,
                           const PointReference& reference, const PointReferenceOptions& options,
                           const std::string& command);

// The points of a point reference folder, refused (InputError naming the file) unless they were
// made for this scene.
PointRadiosity read_reference_points(const std::filesystem::path& dir, const Scene& scene);

}  // namespace hmcr
