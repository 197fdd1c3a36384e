// SPDX-License-Identifier: Apache-2.0
#include "trace/trace_image.h"

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "common/interrupt.h"
#include "common/memory.h"
#include "common/stopwatch.h"
#include "rays/camera.h"
#include "trace/criteria/display_values.h"
#include "trace/criteria/registry.h"
#include "trace/map_allocation.h"
#include "trace/pass_runs.h"
#include "trace/pixel_runs.h"

namespace hmcr {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The fresh pass's seed is the image's with this bit flipped: streams apart from every seed a
// study uses (1, 2, 3, ...).
constexpr std::uint64_t kFreshSeed = std::uint64_t(1) << 62;

// The quadtree's own limits apply where it refines; the map's first pass is a batch of 8.
bool refines_quadtree(const TraceOptions& o) {
    return o.sampler->scheme() == Scheme::quadtree && o.allocation == Allocation::refine;
}

std::uint32_t min_samples_per_pixel(const TraceOptions& o) {
    return refines_quadtree(o) ? kNodeSamples : kBatchSize;
}

void validate(const TraceOptions& o, const Criterion& c) {
    if (o.tree_depth < 1 || o.tree_depth > 12) throw InputError("tree-depth must be in 1..12");
    if (!(o.spp_tolerance > 0 && o.spp_tolerance < 1)) {
        throw InputError("spp-tolerance must be in (0, 1)");
    }
    if (!(o.criterion_exposure >= 0 && std::isfinite(o.criterion_exposure))) {
        throw InputError(fmt::format("criterion-exposure must be a positive number or 0, got {}",
                                     o.criterion_exposure));
    }
    if (o.max_spp && !(*o.max_spp >= kBatchSize && *o.max_spp <= kMostSamplesPerPixel)) {
        throw InputError(fmt::format("max-spp must be in {}..{}, got {}", kBatchSize,
                                     kMostSamplesPerPixel, *o.max_spp));
    }
    if (!std::isnan(o.threshold) && !(o.threshold > 0)) {
        throw InputError("threshold must be positive");
    }
    if (!std::isnan(o.threshold) && c.scheme() != Scheme::uniform &&
        o.allocation == Allocation::map) {
        throw InputError(
            "threshold is for --allocation refine: map spends --spp by the criterion's map of "
            "its first samples, with no threshold");
    }
    if (c.scheme() == Scheme::uniform) {
        if (!(o.spp >= 1 && o.spp <= kMostSamplesPerPixel && o.spp == std::floor(o.spp))) {
            throw InputError(
                fmt::format("spp must be a whole number in 1..1e6 for the uniform "
                            "sampler, got {}",
                            o.spp));
        }
        return;
    }
    const std::uint32_t lo = min_samples_per_pixel(o), hi = max_samples_per_pixel(o);
    if (!(o.spp >= lo && o.spp <= hi)) {
        throw InputError(
            fmt::format("spp must be in {}..{} for sampler {} (its first samples "
                        "and its most in one pixel), got {}",
                        lo, hi, c.name(), o.spp));
    }
}

// The first probe: the first value of the pixel at quantile 1 - (spp - min) / (max - min), so
// that about as many pixels refine as could reach the target if each went to its maximum. Most
// stop well before it, so the first probe lands below the target, and the search approaches
// it from below, where probes cost the fewest samples. 0 when no pixel can refine.
double first_probe(std::vector<double> values, double spp, double min, double max) {
    values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return !(x > 0); }),
                 values.end());
    if (values.empty()) return 0;
    const double q = std::clamp(1 - (spp - min) / (max - min), 0.0, 1.0);
    const auto k = std::ptrdiff_t(q * double(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[std::size_t(k)];
}

// The search: first every pixel's first samples, then the probes.
double search(SampleRuns& runs, const TraceOptions& o, std::vector<ThresholdProbe>& probes,
              Progress& progress) {
    progress.stage("first samples");
    runs.extend(kInf, progress);
    const double start =
        first_probe(runs.first_values(), o.spp, min_samples_per_pixel(o), max_samples_per_pixel(o));
    if (start == 0) {
        throw SppNotReached(
            fmt::format("{} samples per pixel not reached: every pixel's first "
                        "samples are all equal, so nothing refines",
                        o.spp));
    }
    const auto spp_at = [&](double threshold) {
        progress.stage(fmt::format("threshold probe {}", probes.size() + 1));
        const double spp = runs.extend(threshold, progress);
        progress.note(fmt::format("threshold probe {}: {:.4g} -> {:.2f} samples per pixel",
                                  probes.size() + 1, threshold, spp));
        return spp;
    };
    return search_threshold(spp_at, start, {o.spp, o.spp_tolerance}, probes);
}

double choose_threshold(const Criterion& c, SampleRuns& runs, const TraceOptions& o,
                        std::vector<ThresholdProbe>& probes, Progress& progress) {
    if (c.scheme() != Scheme::uniform && std::isnan(o.threshold)) {
        return search(runs, o, probes, progress);
    }
    const double threshold = c.scheme() == Scheme::uniform ? kInf : o.threshold;
    progress.stage("tracing");
    runs.extend(threshold, progress);
    return threshold;
}

RunLimits limits(const TraceOptions& o, const Criterion& c) {
    RunLimits l;
    l.max_depth = o.tree_depth;
    l.max_samples = c.scheme() == Scheme::uniform ? std::uint32_t(o.spp) : max_samples_per_pixel(o);
    return l;
}

std::unique_ptr<SampleRuns> make_runs(const Criterion& c, const TraceOptions& o,
                                      const PixelTracer& pixels) {
    const RunLimits l = limits(o, c);
    if (c.scheme() == Scheme::passes) return make_pass_runs(c, l.max_samples, pixels);
    return std::make_unique<PixelRuns>(c, l, pixels);
}

}  // namespace

std::string TraceOptions::to_string() const {
    return fmt::format(
        "TraceOptions{{sampler={}, spp={}, threshold={}, spp_tolerance={}, "
        "max_spp={}, tree_depth={}, seed={}, threads={}, criterion_exposure={}, fresh={}, "
        "allocation={}, path={}}}",
        sampler->name(), spp, threshold, spp_tolerance, max_spp.value_or(0), tree_depth, seed,
        threads, criterion_exposure, fresh, allocation_name(allocation), path.to_string());
}

std::string allocation_name(Allocation a) { return a == Allocation::map ? "map" : "refine"; }

Allocation parse_allocation(const std::string& name) {
    for (Allocation a : {Allocation::refine, Allocation::map}) {
        if (allocation_name(a) == name) return a;
    }
    throw std::invalid_argument("allocation must be refine or map, got '" + name + "'");
}

void validate_trace_options(const TraceOptions& o) { validate(o, *o.sampler); }

std::uint32_t max_samples_per_pixel(const TraceOptions& o) {
    if (refines_quadtree(o)) {
        return std::uint32_t(1) << (2 * (o.tree_depth + 1));
    }
    if (o.max_spp) return *o.max_spp;
    const double eight_times = std::ceil(8 * o.spp / kBatchSize) * kBatchSize;
    return std::uint32_t(std::clamp(eight_times, double(kBatchSize), double(kMostSamplesPerPixel)));
}

void check_trace_memory(const TraceOptions& o, const View& view) {
    const Criterion& c = *o.sampler;
    const RunLimits l = limits(o, c);
    const double pixels = double(view.width) * double(view.height);
    // Each pixel: its run, the pointer to it, its radiance and its sample count; the map keeps
    // a first batch and a uniform run.
    const bool map = c.scheme() != Scheme::uniform && o.allocation == Allocation::map;
    const std::uint64_t run = map ? 2 * batch_run_bytes(c, kBatchSize) : pixel_run_bytes(c, l);
    const double bytes = pixels * double(run + sizeof(std::unique_ptr<PixelRun>) + sizeof(Rgb) +
                                         sizeof(std::uint32_t));
    const char* lower = refines_quadtree(o) ? "lower --tree-depth or --width"
                        : c.scheme() == Scheme::batches || c.scheme() == Scheme::passes
                            ? "lower --max-spp (default 8 x --spp) or --width"
                            : "lower --width";
    const std::uint32_t most = refines_quadtree(o) ? max_samples_per_pixel(o) : l.max_samples;
    require_memory(
        bytes,
        fmt::format("tracing {} x {} pixels at up to {} samples each{}", view.width, view.height,
                    most, c.scheme() == Scheme::uniform ? "" : ", every sample kept,"),
        lower);
}

SampleCounts TraceResult::counts() const {
    SampleCounts c;
    if (samples.empty()) return c;
    const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
    double sum = 0;
    for (std::uint32_t n : samples) sum += n;
    return {*lo, *hi, sum / double(samples.size())};
}

namespace {

TraceResult trace_in_arena(const PathTracer& tracer, const View& view, const TraceOptions& o,
                           Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const Criterion& chosen = *o.sampler;
    validate(o, chosen);
    check_trace_memory(o, view);
    throw_if_interrupted();
    const bool adaptive = chosen.scheme() != Scheme::uniform;
    std::unique_ptr<Criterion> on_display;
    if (adaptive && o.criterion_exposure > 0) {
        on_display = on_display_values(chosen, o.criterion_exposure);
    }
    const Criterion& criterion = on_display ? *on_display : chosen;
    const Camera camera = make_camera(view);
    const PixelTracer pixels(tracer, camera, o.seed);
    TraceResult r;
    if (adaptive && o.allocation == Allocation::map) {
        const PixelTracer fresh(tracer, camera, o.seed ^ kFreshSeed);
        MapTrace m = trace_from_map(criterion, pixels, o.fresh ? &fresh : nullptr, o.spp,
                                    max_samples_per_pixel(o), progress);
        r.image = std::move(m.image);
        r.samples = std::move(m.samples);
        r.rays = m.rays;
        r.rays_traced = m.rays_traced;
        r.seconds = seconds_since(start);
        return r;
    }
    const std::unique_ptr<SampleRuns> runs = make_runs(criterion, o, pixels);
    const double threshold = choose_threshold(criterion, *runs, o, r.probes, progress);
    r.threshold = criterion.scheme() == Scheme::uniform ? r.threshold : threshold;
    r.image = runs->image(threshold);
    r.samples = runs->samples(threshold);
    r.rays = runs->rays(threshold);
    r.rays_traced = runs->rays_traced();
    if (adaptive && o.fresh) {
        progress.stage("fresh samples");
        const PixelTracer fresh(tracer, camera, o.seed ^ kFreshSeed);
        r.rays = 0;
        r.image = fresh_image(fresh, r.samples, r.rays, progress);
        r.rays_traced += r.rays;
    }
    r.seconds = seconds_since(start);
    return r;
}

}  // namespace

// In a task arena of o.threads (0: TBB's default), leaving the process's other work as it was.
TraceResult trace_image(const PathTracer& tracer, const View& view, const TraceOptions& o,
                        Progress& progress) {
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    TraceResult r;
    arena.execute([&] { r = trace_in_arena(tracer, view, o, progress); });
    return r;
}

}  // namespace hmcr
