// SPDX-License-Identifier: Apache-2.0
// A path-traced image of a view (`hmcr trace`): the path tracer (trace/path_tracer.h) sampled
// per pixel by a sampling criterion (trace/criteria/), uniformly or adaptively. With an adaptive
// criterion the threshold is found for a mean number of samples per pixel
// (trace/threshold_search.h) unless one is given. The image is the box-filtered mean radiance of
// each pixel's samples and does not depend on the thread count.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/progress.h"
#include "image/image.h"
#include "meshes/scene.h"
#include "trace/criteria/registry.h"
#include "trace/path_tracer.h"
#include "trace/pixel_run.h"
#include "trace/threshold_search.h"

namespace hmcr {

// The most samples one pixel takes: the uniform sampler's spp, and an adaptive one's max_spp.
inline constexpr std::uint32_t kMostSamplesPerPixel = 1'000'000;

// How an adaptive sampler spends the budget (docs/design.md §10.6, §10.9): `refine`, its scheme
// refines each pixel until the threshold that gives the mean spp (trace/threshold_search.h);
// `map`, the papers' two passes (trace/map_allocation.h).
enum class Allocation { refine, map };

// "refine", "map"; parse_allocation throws std::invalid_argument on anything else.
std::string allocation_name(Allocation a);
Allocation parse_allocation(const std::string& name);

struct TraceOptions {
    const Criterion* sampler = &uniform_criterion();  // trace/criteria/registry.h
    double spp = 16;  // mean samples per pixel: exact for uniform (a whole
                      // number), the search's target otherwise
    double threshold = std::numeric_limits<double>::quiet_NaN();  // > 0: fixed, no search
    double spp_tolerance = 0.02;  // accepted relative distance of the mean to spp
    // most samples of one pixel, batch samplers: 8..kMostSamplesPerPixel; none: 8 x spp
    std::optional<std::uint32_t> max_spp;
    int tree_depth = 4;      // entropy samplers' quadtree depth limit, 1..12
    std::uint64_t seed = 1;  // keys every sample's stream
    int threads = 0;         // 0 = all cores; the image does not depend on it
    // > 0: adaptive criteria see display values, radiance x this clamped to [0, 1]
    // (trace/criteria/display_values.h); 0: physical radiance
    double criterion_exposure = 0;
    // Adaptive samplers: the image from fresh samples at the counts the criterion chose
    // (fresh_image of trace/pixel_runs.h: unbiased, and about twice the rays)
    bool fresh = false;
    Allocation allocation = Allocation::refine;  // adaptive samplers
    PathOptions path;

    std::string to_string() const;
};

struct SampleCounts {
    std::uint32_t min = 0, max = 0;
    double mean = 0;
};

struct TraceResult {
    Image image;                                                  // linear radiance
    std::vector<std::uint32_t> samples;                           // per pixel, row-major
    double threshold = std::numeric_limits<double>::quiet_NaN();  // used; NaN for uniform
    std::vector<ThresholdProbe> probes;                           // of the search
    std::uint64_t rays = 0;                                       // cast by the image's samples
    std::uint64_t rays_traced = 0;  // also by samples the search took beyond the threshold
    double seconds = 0;

    SampleCounts counts() const;
};

// The most samples one pixel can get with these options (a quadtree refining: 4^(depth + 1)).
std::uint32_t max_samples_per_pixel(const TraceOptions& options);

// Throws InputError on bad options: a target outside what the sampler can give. Commands call it
// before any work; trace_image again.
void validate_trace_options(const TraceOptions& options);

// Throws InputError naming the option to lower when tracing the view could need more memory
// than the machine holds (require_memory of common/memory.h): an adaptive sampler keeps every
// sample of every pixel, up to the most a pixel can take (pixel_run_bytes of trace/pixel_run.h).
// Commands call it before any work; trace_image again.
void check_trace_memory(const TraceOptions& options, const View& view);

// Throws InputError on bad options or memory, SppNotReached when the search fails, and
// Interrupted (common/interrupt.h) within a pixel after a SIGINT, SIGTERM or SIGHUP.
TraceResult trace_image(const PathTracer& tracer, const View& view, const TraceOptions& options,
                        Progress& progress = no_progress());

}  // namespace hmcr
