// SPDX-License-Identifier: Apache-2.0
// The path tracer's options (trace/trace_image.h) on the command line, shared by `trace`,
// `trace-reference` and the sampling study (`study --samplers`).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <set>
#include <string>

#include "meshes/scene.h"
#include "trace/trace_image.h"

namespace hmcr {

// What the flags hold until run time checks and applies them.
struct TraceFlags {
    std::string estimator = "mis";
    std::string allocation = "refine";
    std::optional<int> width;  // render at this width, the view's aspect kept
};

// Adds every trace flag to `command`, bound to `options` and `flags`, except those named in
// `except` ("sampler", "spp", "seed", "threshold", "width", "threads", "criterion-exposure":
// what a command sets itself; "adaptive": every flag of the adaptive samplers, for a command
// that traces with the uniform sampler alone).
void add_trace_flags(CLI::App& command, TraceOptions& options, TraceFlags& flags,
                     const std::set<std::string>& except = {});

// Checks the flags that name things (the estimator, the allocation) and applies them to
// `options`;
// throws InputError.
void apply_trace_flags(const TraceFlags& flags, TraceOptions& options);

// The view at flags.width pixels wide (the height follows the aspect ratio), or unchanged.
View sized_view(const View& view, const TraceFlags& flags);

}  // namespace hmcr
