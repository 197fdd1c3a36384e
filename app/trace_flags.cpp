// SPDX-License-Identifier: Apache-2.0
#include "app/trace_flags.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/count.h"
#include "common/error.h"
#include "trace/criteria/registry.h"

namespace hmcr {
namespace {

bool wanted(const std::set<std::string>& except, const std::string& name) {
    return except.count(name) == 0;
}

void add_sampling_flags(CLI::App& cmd, TraceOptions& o, TraceFlags& flags,
                        const std::set<std::string>& except) {
    if (wanted(except, "sampler")) {
        // Resolved here, where the name is read.
        cmd.add_option_function<std::string>(
               "--sampler",
               [&o](const std::string& name) {
                   o.sampler = &find_named(criterion_registry(), name);
               },
               "pixel sampling criterion (`hmcr samplers`)")
            ->default_str(std::string(o.sampler->name()));
    }
    if (wanted(except, "spp")) {
        cmd.add_option("--spp", o.spp,
                       "mean samples per pixel (exact for uniform; adaptive "
                       "samplers find their threshold for it)")
            ->capture_default_str();
    }
    if (wanted(except, "threshold")) {
        cmd.add_option("--threshold", o.threshold,
                       "adaptive samplers: this refinement threshold instead of the search");
    }
    if (!wanted(except, "adaptive")) return;  // the uniform sampler alone: none of the rest
    cmd.add_option("--spp-tolerance", o.spp_tolerance, "accepted relative distance to --spp")
        ->capture_default_str();
    cmd.add_option_function<std::uint32_t>(
        "--max-spp", [&o](const std::uint32_t& n) { o.max_spp = n; },
        "most samples in one pixel (default 8 x spp)");
    cmd.add_option("--tree-depth", o.tree_depth, "subpixel quadtree depth limit (entropy samplers)")
        ->capture_default_str();
    if (wanted(except, "criterion-exposure")) {
        cmd.add_option("--criterion-exposure", o.criterion_exposure,
                       "adaptive samplers judge radiance x this, clamped to [0, 1] (display "
                       "values); 0: physical radiance")
            ->capture_default_str();
    }
    cmd.add_flag("--fresh", o.fresh,
                 "adaptive samplers: the image from fresh samples at the chosen counts "
                 "(unbiased, about twice the rays)");
    cmd.add_option("--allocation", flags.allocation,
                   "adaptive samplers: refine (each pixel until the threshold that gives --spp) "
                   "or map (8 uniform samples per pixel, then the rest of the budget in "
                   "proportion to the criterion's map of them)")
        ->capture_default_str();
}

}  // namespace

void add_trace_flags(CLI::App& command, TraceOptions& options, TraceFlags& flags,
                     const std::set<std::string>& except) {
    add_sampling_flags(command, options, flags, except);
    if (wanted(except, "seed")) {
        command.add_option("--seed", options.seed, "keys every sample's random stream")
            ->transform(count_notation())
            ->capture_default_str();
    }
    if (wanted(except, "threads")) {
        command
            .add_option("--threads", options.threads,
                        "worker threads, 0 = all cores; images do not depend on it")
            ->capture_default_str();
    }
    command.add_option("--bounces", options.path.max_depth, "most bounces of a path")
        ->capture_default_str();
    command
        .add_option("--estimator", flags.estimator,
                    "mis (next-event + BSDF sampling), nee or bsdf alone")
        ->capture_default_str();
    if (wanted(except, "width")) {
        command.add_option_function<int>(
            "--width", [&flags](const int& w) { flags.width = w; },
            "render at this width (the view's aspect kept)");
    }
}

void apply_trace_flags(const TraceFlags& flags, TraceOptions& o) {
    try {
        o.path.estimator = parse_estimator(flags.estimator);
        o.allocation = parse_allocation(flags.allocation);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    if (o.path.max_depth < 0 || o.path.max_depth > 100000) {
        throw InputError("bounces must be in 0..100000");
    }
    if (o.threads < 0 || o.threads > 4096) throw InputError("threads must be in 0..4096");
    if (flags.width && (*flags.width < 1 || *flags.width > 16384)) {
        throw InputError(fmt::format("width must be in 1..16384, got {}", *flags.width));
    }
}

View sized_view(const View& view, const TraceFlags& flags) {
    if (!flags.width) return view;
    View v = view;
    v.width = *flags.width;
    v.height = std::max(1, int(std::lround(double(v.width) * view.height / view.width)));
    return v;
}

}  // namespace hmcr
