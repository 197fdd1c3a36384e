// SPDX-License-Identifier: Apache-2.0
// The scene's information measures and the path tracer.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/trace_flags.h"
#include "information/scene_information.h"
#include "python/bindings.h"
#include "python/python_progress.h"
#include "python/values.h"
#include "rays/patch.h"
#include "trace/criteria/registry.h"
#include "trace/path_tracer.h"
#include "trace/trace_image.h"

namespace hmcr::python {

using nlohmann::json;

// `hmcr info SCENE --json` (patches) or `hmcr info SOLUTION.vtp --json` (leaves): the entropies
// and mutual information of the channel whose states are `states`.
py::object channel_information(const ChannelStates& states, std::uint64_t lines,
                               const std::string& method, std::uint64_t seed, py::object progress) {
    if (lines < 16) throw InputError("lines must be at least 16");
    LineOptions o;
    o.method = parse_line_method(method);
    o.lines = lines;
    o.seed = seed;
    const InformationMeasures m = run_released(
        std::move(progress), [&](Progress& told) { return scene_information(states, o, told); });
    json j = to_json(m);
    j["open_fraction"] = double(m.samples_open) / double(std::max<std::size_t>(1, m.samples));
    return python_json(j);
}

namespace {

// The trace flags that name things (estimator, allocation) applied as the command line applies
// them, with the path's bounces.
void apply_trace_names(TraceOptions& o, const std::string& estimator, const std::string& allocation,
                       int bounces, std::optional<int> width, TraceFlags& flags) {
    o.path.max_depth = bounces;
    flags.estimator = estimator;
    flags.allocation = allocation;
    flags.width = width;
    apply_trace_flags(flags, o);
}

// `hmcr trace SCENE --pfm`'s image and the samples each pixel took, from the path tracer.
py::dict trace_scene(const Scene& scene, const std::string& view, const std::string& sampler,
                     double spp, std::optional<double> threshold, double spp_tolerance,
                     std::optional<std::uint32_t> max_spp, int tree_depth, std::uint64_t seed,
                     int threads, bool fresh, const std::string& allocation, int bounces,
                     const std::string& estimator, std::optional<int> width, py::object progress) {
    TraceOptions o;
    o.sampler = &find_named(criterion_registry(), sampler);
    o.spp = spp;
    if (threshold) o.threshold = *threshold;
    o.spp_tolerance = spp_tolerance;
    o.max_spp = max_spp;
    o.tree_depth = tree_depth;
    o.seed = seed;
    o.threads = threads;
    o.fresh = fresh;
    TraceFlags flags;
    apply_trace_names(o, estimator, allocation, bounces, width, flags);
    validate_trace_options(o);
    const View v = sized_view(find_view(scene, view), flags);
    check_trace_memory(o, v);
    const TraceResult r = run_released(std::move(progress), [&](Progress& told) {
        const PathTracer tracer(build_patch_set(scene.mesh), o.path);
        return trace_image(tracer, v, o, told);
    });
    py::array_t<std::uint32_t> samples({py::ssize_t(v.height), py::ssize_t(v.width)});
    std::copy(r.samples.begin(), r.samples.end(), samples.mutable_data());
    py::dict d;
    d["image"] = image_array(r.image);
    d["samples"] = samples;
    d["threshold"] = r.threshold;
    d["rays"] = r.rays;
    d["seconds"] = r.seconds;
    return d;
}

}  // namespace

void bind_measures(py::module_& m) {
    m.def(
        "information",
        [](const Scene& scene, std::uint64_t lines, const std::string& method, std::uint64_t seed,
           py::object progress) {
            return channel_information(patch_states(build_patch_set(scene.mesh)), lines, method,
                                       seed, std::move(progress));
        },
        py::arg("scene"), py::arg("lines") = LineOptions{}.lines, py::arg("method") = "local",
        py::arg("seed") = LineOptions{}.seed, py::arg("progress") = py::none(),
        "`hmcr info SCENE --json`: the entropies and mutual information of the scene's patches");

    m.def("trace", &trace_scene, py::arg("scene"), py::arg("view") = "",
          py::arg("sampler") = "uniform", py::arg("spp") = TraceOptions{}.spp,
          py::arg("threshold") = py::none(),
          py::arg("spp_tolerance") = TraceOptions{}.spp_tolerance, py::arg("max_spp") = py::none(),
          py::arg("tree_depth") = TraceOptions{}.tree_depth, py::arg("seed") = TraceOptions{}.seed,
          py::arg("threads") = 0, py::arg("fresh") = false, py::arg("allocation") = "refine",
          py::arg("bounces") = PathOptions{}.max_depth, py::arg("estimator") = "mis",
          py::arg("width") = py::none(), py::arg("progress") = py::none(),
          "`hmcr trace`: a path-traced view (image, H x W x 3) and each pixel's samples");
}

}  // namespace hmcr::python
