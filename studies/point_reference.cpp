// SPDX-License-Identifier: Apache-2.0
#include "studies/point_reference.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_names.h"
#include "common/interrupt.h"
#include "common/json_fields.h"
#include "common/memory.h"
#include "common/stopwatch.h"
#include "meshes/patch_mesh.h"
#include "rays/embree_scene.h"
#include "rays/rng.h"
#include "studies/reference.h"
#include "viz/renderer.h"

namespace hmcr {
namespace {

// Keys the points' paths apart from every other stream of the same seed (docs/design.md §9.1).
constexpr std::uint64_t kPointKey = 0x706f696e7473ULL;  // "points"

// Points are estimated a block at a time between the progress and interruption checks.
constexpr std::size_t kBlock = 4096;

// The memory of a point while it is made and written: the point, both seeds' estimates and
// variances, their copies in the VTK arrays.
constexpr double kBytesPerPoint = sizeof(SurfacePoint) + 4 * sizeof(Rgb) + 160;

struct Estimate {
    Rgb mean = Rgb::Zero(), variance = Rgb::Zero();
    std::uint64_t rays = 0;
};

// One point's B: E plus the mean of `paths` estimates of B - E, and the variance of that mean
// from the estimates' sample variance.
Estimate estimate_point(const PathTracer& tracer, const SurfacePoint& p, const Rgb& emission,
                        std::uint64_t paths, std::uint64_t seed, std::uint64_t index) {
    Rng rng(seed, kPointKey, index);
    Rgb sum = Rgb::Zero(), squares = Rgb::Zero();
    Estimate e;
    for (std::uint64_t k = 0; k < paths; ++k) {
        std::uint32_t rays = 0;
        const Rgb r = tracer.reflected_radiosity(p.position, p.patch, p.side, rng, rays);
        sum += r;
        squares += r * r;
        e.rays += rays;
    }
    const double n = double(paths);
    const Rgb mean = sum / n;
    e.mean = emission + mean;
    // The sample variance, never below 0 where rounding takes sum^2 / n above the squares.
    e.variance = ((squares - n * mean * mean) / (n - 1)).cwiseMax(0.0) / n;
    return e;
}

// Points [first, last) of one seed, into the vectors at the same indices.
std::uint64_t estimate_range(const PathTracer& tracer, const PointRadiosity& r,
                             const std::vector<Rgb>& emission, std::uint64_t seed,
                             std::size_t first, std::size_t last, std::vector<Rgb>& mean,
                             std::vector<Rgb>& variance, Progress& progress, double done,
                             double share) {
    std::uint64_t rays = 0;
    for (std::size_t b = first; b < last; b += kBlock) {
        throw_if_interrupted();
        const std::size_t end = std::min(last, b + kBlock);
        std::vector<std::uint64_t> block_rays(end - b, 0);
        tbb::parallel_for(b, end, [&](std::size_t i) {
            set_tracing_float_mode();
            const Estimate e =
                estimate_point(tracer, r.points[i], emission[i], r.paths, seed, std::uint64_t(i));
            mean[i] = e.mean;
            variance[i] = e.variance;
            block_rays[i - b] = e.rays;
        });
        for (std::uint64_t n : block_rays) rays += n;
        progress.advance(done + share * double(end - first) /
                                    double(std::max<std::size_t>(1, last - first)));
    }
    return rays;
}

// Each rank's block of points, then every rank's blocks gathered, in rank order.
std::uint64_t estimate_points(const PathTracer& tracer, PointRadiosity& r,
                              const std::vector<Rgb>& emission, Progress& progress,
                              const Ranks& ranks) {
    const std::size_t n = r.points.size(), size = std::size_t(ranks.size());
    const auto start_of = [&](std::size_t rank) { return n * rank / size; };
    const std::size_t first = start_of(std::size_t(ranks.rank())),
                      last = start_of(std::size_t(ranks.rank()) + 1);
    std::uint64_t rays = 0;
    for (int s = 0; s < 2; ++s) {
        r.radiosity[s].assign(n, Rgb::Zero());
        r.variance[s].assign(n, Rgb::Zero());
        rays += estimate_range(tracer, r, emission, r.seed + std::uint64_t(s), first, last,
                               r.radiosity[s], r.variance[s], progress, 0.5 * s, 0.5);
    }
    if (size == 1) return rays;
    // Each rank sends its block of the four vectors and its rays; the blocks land in place.
    std::string bytes;
    const auto append = [&](const std::vector<Rgb>& v) {
        for (std::size_t i = first; i < last; ++i) {
            bytes.append(reinterpret_cast<const char*>(v[i].data()), 3 * sizeof(double));
        }
    };
    for (int s = 0; s < 2; ++s) {
        append(r.radiosity[s]);
        append(r.variance[s]);
    }
    bytes.append(reinterpret_cast<const char*>(&rays), sizeof rays);
    const std::vector<std::string> all = ranks.gather_all(bytes);
    std::uint64_t total = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
        const std::size_t a = start_of(k), count = start_of(k + 1) - a;
        const char* at = all[k].data();
        for (int s = 0; s < 2; ++s) {
            for (std::vector<Rgb>* v : {&r.radiosity[s], &r.variance[s]}) {
                for (std::size_t i = a; i < a + count; ++i) {
                    std::memcpy((*v)[i].data(), at, 3 * sizeof(double));
                    at += 3 * sizeof(double);
                }
            }
        }
        std::uint64_t block_rays = 0;
        std::memcpy(&block_rays, at, sizeof block_rays);
        total += block_rays;
    }
    return total;
}

double squared(const Rgb& c) { return c.matrix().squaredNorm(); }

}  // namespace

PatchSet diffuse_patch_set(const Scene& scene) {
    PatchSet set = build_patch_set(scene.mesh);
    for (PatchMaterial& m : set.materials) m.specular = Rgb::Zero();
    return set;
}

std::vector<Rgb> point_emission(const PatchSet& set, const std::vector<SurfacePoint>& points) {
    std::vector<Rgb> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        out[i] = set.material(points[i].patch, points[i].side).emission;
    }
    return out;
}

void validate_point_reference(const Scene& scene, const PointReferenceOptions& o) {
    if (o.points < 1) throw InputError("points must be at least 1");
    if (o.paths < 2) throw InputError("paths must be at least 2 (a point's variance needs two)");
    if (o.points > std::uint64_t(1) << 40) throw InputError("points must be at most 2^40");
    TraceOptions views = o.views;
    views.sampler = &uniform_criterion();
    validate_trace_options(views);
    for (const View& v : scene.views) check_trace_memory(views, v);
    const PatchSet set = build_patch_set(scene.mesh);
    const std::uint64_t n = stratified_point_count(set, o.points);
    require_memory(double(n) * kBytesPerPoint, fmt::format("a point reference of {} points", n),
                   "use fewer --points");
}

std::uint64_t paths_for_target_noise(double noise, std::uint64_t paths) {
    const double ratio = noise / kTargetNoise;
    return std::uint64_t(std::ceil(double(paths) * ratio * ratio));
}

PointReferenceReport point_report(const PointRadiosity& r, const std::vector<Rgb>& emission) {
    PointReferenceReport out;
    double reflected = 0, noise = 0, check = 0, check_variance = 0, area = 0;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const double w = r.points[i].weight;
        const Rgb v = r.mean_variance(i);
        reflected += w * (squared(r.mean(i) - emission[i]) - v.sum());
        noise += w * v.sum();
        // (B1 - B2)^2 less its expectation v1 + v2, and that term's variance for a normal
        // difference: 2 (v1 + v2)^2 per channel.
        const Rgb both = r.variance[0][i] + r.variance[1][i];
        check += w * (squared(r.radiosity[0][i] - r.radiosity[1][i]) - both.sum());
        check_variance += w * w * 2 * squared(both);
        area += w;
    }
    if (reflected > 0) {
        out.noise = std::sqrt(noise / reflected);
        out.seed_check = check / reflected;
        out.seed_check_se = std::sqrt(check_variance) / reflected;
    }
    out.area_per_point = r.points.empty() ? 0 : area / double(r.points.size());
    return out;
}

PointRadiosity estimate_reference_points(const Scene& scene, const PathTracer& tracer,
                                         const PointReferenceOptions& o, Progress& progress,
                                         const Ranks& ranks, std::uint64_t& rays) {
    PointRadiosity r;
    r.points = stratified_points(tracer.patches(), o.points, o.strata_seed);
    r.paths = o.paths;
    r.seed = o.seed;
    r.scene = scene.name;
    r.geometry_hash = geometry_hash(scene.mesh);
    r.patch_count = scene.mesh.n_faces();
    const std::vector<Rgb> emission = point_emission(tracer.patches(), r.points);
    progress.stage(fmt::format("{} points, 2 seeds x {} paths", r.points.size(), o.paths));
    rays = estimate_points(tracer, r, emission, progress, ranks);
    return r;
}

PointReference compute_point_reference(const Scene& scene, const PointReferenceOptions& o,
                                       Progress& progress, const Ranks& ranks) {
    validate_point_reference(scene, o);
    const auto start = std::chrono::steady_clock::now();
    PointReference ref;
    const PathTracer tracer(diffuse_patch_set(scene), o.path);
    std::uint64_t rays = 0;
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    arena.execute(
        [&] { ref.points = estimate_reference_points(scene, tracer, o, progress, ranks, rays); });
    ref.report = point_report(ref.points, point_emission(tracer.patches(), ref.points.points));
    ref.report.rays = rays;
    TraceOptions views = o.views;
    views.path = o.path;
    views.threads = o.threads;
    views.seed = o.seed;
    ref.views = trace_views(tracer, scene.views, views, progress);
    ref.seconds = seconds_since(start);
    return ref;
}

std::vector<std::filesystem::path> point_reference_files(const std::filesystem::path& dir,
                                                         const Scene& scene) {
    std::vector<std::filesystem::path> files = traced_reference_files(dir, scene);
    files.push_back(dir / "points.vtp");
    return files;
}

void write_point_reference(OutputSet& out, const std::filesystem::path& dir, const Scene& scene,
                           const PointReference& ref, const PointReferenceOptions& o,
                           const std::string& command) {
    write_point_radiosity(out.temp(dir / "points.vtp"), ref.points);
    const nlohmann::json views = write_view_images(out, dir, ref.views);
    const PointReferenceReport& rep = ref.report;
    nlohmann::json j = {
        {"command", command},
        {"hmcr_version", HMCR_VERSION},
        {"reference",
         {{"kind", "points"},
          {"scene", scene.name},
          {"scene_file", scene_file(scene)},
          {"points", ref.points.points.size()},
          {"points_target", o.points},
          {"strata_seed", o.strata_seed},
          {"paths", o.paths},
          {"seeds", {o.seed, o.seed + 1}},
          {"path",
           {{"estimator", estimator_name(o.path.estimator)},
            {"max_depth", o.path.max_depth},
            {"roulette_depth", o.path.roulette_depth}}},
          {"report",
           {{"what",
             "relative to the reflected radiosity, as an object error: noise, the standard error "
             "of the seeds' mean; seed_check, the seeds' squared difference less its expected "
             "value (zero within seed_check_se when the variances are right)"},
            {"noise", rep.noise},
            {"seed_check", rep.seed_check},
            {"seed_check_se", rep.seed_check_se},
            {"area_per_point_m2", rep.area_per_point},
            {"rays", rep.rays}}},
          {"view_spp", o.views.spp},
          {"seconds", ref.seconds},
          {"views", views}}}};
    if (scene.source.empty()) j["reference"].erase("scene_file");
    write_text_atomically(out.temp(dir / "reference.json"), j.dump(2) + "\n");
}

PointRadiosity read_reference_points(const std::filesystem::path& dir, const Scene& scene) {
    const std::filesystem::path file = dir / "points.vtp";
    PointRadiosity r = read_point_radiosity(file);
    if (r.geometry_hash != geometry_hash(scene.mesh) ||
        r.patch_count != std::uint64_t(scene.mesh.n_faces())) {
        throw InputError(file.string(), fmt::format("made for scene {} of other geometry, not {}",
                                                    quote(r.scene), quote(scene.name)));
    }
    const FaceMaterials materials(scene.mesh);
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const SurfacePoint& p = r.points[i];
        if (p.side == kBack &&
            materials.back_index(scene.mesh.face_handle(int(p.patch))) == kOneSided) {
            throw InputError(
                file.string(),
                fmt::format("point {} is on the back of patch {}, which is one-sided", i, p.patch));
        }
    }
    return r;
}

}  // namespace hmcr
