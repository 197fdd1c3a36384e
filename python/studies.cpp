// SPDX-License-Identifier: Apache-2.0
// References and studies, into folders as the command line writes them, the studies' cells back.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/named_list.h"
#include "app/run_summary.h"
#include "app/trace_flags.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "python/bindings.h"
#include "python/python_progress.h"
#include "python/values.h"
#include "studies/object_error_json.h"
#include "studies/point_reference.h"
#include "studies/reference.h"
#include "studies/sampling_study.h"
#include "studies/study.h"
#include "trace/criteria/registry.h"

namespace hmcr::python {
namespace {

using nlohmann::json;

// `hmcr reference SCENE --kind mesh -o OUTPUT`: a uniform mesh of elements of at most max_area
// m^2 solved with two seeds, its views' images, its convergence and its check, in OUTPUT.
// Returns the summary hmcr prints, as a dict.
py::object mesh_reference(const Scene& scene, const std::string& output, double max_area,
                          int samples, std::optional<std::uint64_t> check_points,
                          py::object progress, const py::kwargs& keywords) {
    for (const auto& [key, value] : keywords) {
        const std::string name = py::str(key);
        if (kNotReferenceSettings.count(name)) {
            throw InputError(
                fmt::format("{} is not a reference's setting: its uniform mesh has "
                            "no oracle, no refinement limits and no clusters",
                            name));
        }
    }
    if (!(max_area > 0)) throw InputError("max-area must be positive");
    if (samples < 1 || samples > 16) throw InputError("samples must be in 1..16");
    ReferenceOptions o;
    o.max_area = max_area;
    o.samples_per_axis = samples;
    o.check_points = check_points;
    o.solver = solve_options(scene, keywords, o.solver, kReferenceOwnSettings);
    const std::filesystem::path dir(output);
    refuse_overwriting(reference_files(dir, scene), scene.inputs);
    OutputSet out(reference_files(dir, scene), dir);
    const Reference ref = run_released(
        std::move(progress), [&](Progress& told) { return compute_reference(scene, o, told); });
    RunTimings timings;
    timings.total_seconds = ref.seconds;
    write_reference(out, dir, scene, ref, o,
                    run_summary(scene, ref.solution, timings, "python: hmcr.mesh_reference",
                                (dir / "reference.vtp").string()));
    out.commit();
    return python_json(
        {{"leaves", ref.solution.stats.leaves},
         {"seconds", ref.seconds},
         {"seed_difference", object_error_json(ref.object_error)},
         {"truncation",
          {ref.truncation.relative[0], ref.truncation.relative[1], ref.truncation.relative[2]}},
         {"discretisation", object_error_json(ref.discretisation)}});
}

// table.json's cells of a study folder.
py::object study_cells(const std::string& output) {
    const py::object text =
        py::module_::import("pathlib").attr("Path")(output).attr("joinpath")("table.json");
    return py::module_::import("json").attr("loads")(text.attr("read_text")())["cells"];
}

// `hmcr study SCENE --reference DIR --budgets ... -o OUTPUT` without its plots: every oracle x
// budget x seed into OUTPUT (cells, tables, images, meshes), resumed where OUTPUT holds cells of
// the same settings. Returns table.json's cells.
py::object meshing_study(const Scene& scene, const std::string& reference,
                         const std::vector<std::size_t>& budgets, const std::string& output,
                         const std::vector<std::string>& oracles, int seeds,
                         std::uint64_t rays_per_leaf, std::optional<std::uint64_t> mesh_rays,
                         double budget_tolerance, int samples, py::object progress,
                         const py::kwargs& keywords) {
    for (const char* per_cell : {"oracle", "epsilon"}) {
        if (keywords.contains(per_cell)) {
            throw InputError(
                fmt::format("{} is set per cell: give oracles=[...] (a budget "
                            "search finds each cell's epsilon)",
                            per_cell));
        }
    }
    StudyOptions o;
    o.reference = reference;
    o.output = output;
    o.budgets = budgets;
    o.oracles = named_list(oracle_registry(), oracles);
    o.seeds = seeds;
    o.rays_per_leaf = rays_per_leaf;
    o.mesh_rays = mesh_rays;
    o.budget_tolerance = budget_tolerance;
    o.samples_per_axis = samples;
    o.solver = solve_options(scene, keywords);
    validate_study(o);
    refuse_nested_dirs(o.output, o.reference);
    refuse_overwriting(study_output_files(scene, o), scene.inputs);
    run_released(std::move(progress), [&](Progress& told) { run_study(scene, o, told); });
    return study_cells(output);
}

// `hmcr reference SCENE --kind points -o OUTPUT`: radiosity at stratified points, path-traced
// with two seeds, and the views traced uniformly. Returns what it says of itself.
py::object points_reference(const Scene& scene, const std::string& output, std::uint64_t points,
                            std::uint64_t paths, std::uint64_t seed, std::uint64_t strata_seed,
                            int threads, double spp, int bounces, const std::string& estimator,
                            std::optional<int> width, py::object progress) {
    PointReferenceOptions o;
    o.points = points;
    o.paths = paths;
    o.seed = seed;
    o.strata_seed = strata_seed;
    o.threads = threads;
    o.views.spp = spp;
    TraceFlags flags;
    apply_trace_names(o.views, estimator, "refine", bounces, width, flags);
    o.path = o.views.path;
    Scene sized = scene;
    for (View& v : sized.views) v = sized_view(v, flags);
    validate_point_reference(sized, o);
    const std::filesystem::path dir(output);
    refuse_overwriting(point_reference_files(dir, sized), sized.inputs);
    OutputSet out(point_reference_files(dir, sized), dir);
    const PointReference ref = run_released(std::move(progress), [&](Progress& told) {
        return compute_point_reference(sized, o, told);
    });
    write_point_reference(out, dir, sized, ref, o, "python: hmcr.points_reference");
    out.commit();
    const PointReferenceReport& r = ref.report;
    return python_json({{"points", ref.points.points.size()},
                        {"area_per_point", r.area_per_point},
                        {"noise", r.noise},
                        {"seed_check", r.seed_check},
                        {"seed_check_se", r.seed_check_se},
                        {"rays", r.rays},
                        {"seconds", ref.seconds}});
}

// `hmcr study SCENE --reference DIR --samplers ... -o OUTPUT` without its plots: every pixel
// sampler x mean spp x seed. Returns table.json's cells.
py::object sampling_study(const Scene& scene, const std::string& reference,
                          const std::string& output, const std::vector<std::string>& samplers,
                          const std::vector<double>& spps, int seeds, std::uint64_t seed,
                          int threads, int tree_depth, bool fresh, const std::string& allocation,
                          int bounces, const std::string& estimator, bool display_criteria,
                          py::object progress) {
    SamplingStudyOptions o;
    o.reference = reference;
    o.output = output;
    o.samplers = named_list(criterion_registry(), samplers);
    o.spps = spps;
    o.seeds = seeds;
    o.trace.seed = seed;
    o.trace.threads = threads;
    o.trace.tree_depth = tree_depth;
    o.trace.fresh = fresh;
    o.display_criteria = display_criteria;
    TraceFlags flags;
    apply_trace_names(o.trace, estimator, allocation, bounces, std::nullopt, flags);
    validate_sampling_study(o);
    refuse_nested_dirs(o.output, o.reference);
    refuse_overwriting(sampling_study_output_files(scene, o), scene.inputs);
    run_released(std::move(progress), [&](Progress& told) { run_sampling_study(scene, o, told); });
    return study_cells(output);
}

}  // namespace

void bind_studies(py::module_& m) {
    m.def("mesh_reference", &mesh_reference, py::arg("scene"), py::arg("output"),
          py::arg("max_area") = ReferenceOptions{}.max_area,
          py::arg("samples") = ReferenceOptions{}.samples_per_axis,
          py::arg("check_points") = py::none(), py::arg("progress") = py::none(),
          "`hmcr reference --kind mesh`: a converged uniform-mesh reference in a folder");

    m.def("points_reference", &points_reference, py::arg("scene"), py::arg("output"),
          py::arg("points") = PointReferenceOptions{}.points,
          py::arg("paths") = PointReferenceOptions{}.paths, py::arg("seed") = 1,
          py::arg("strata_seed") = 0, py::arg("threads") = 0,
          py::arg("spp") = PointReferenceOptions{}.views.spp,
          py::arg("bounces") = PathOptions{}.max_depth, py::arg("estimator") = "mis",
          py::arg("width") = py::none(), py::arg("progress") = py::none(),
          "`hmcr reference --kind points`: radiosity at stratified points, path-traced");

    m.def("meshing_study", &meshing_study, py::arg("scene"), py::arg("reference"),
          py::arg("budgets"), py::arg("output"),
          py::arg("oracles") = std::vector<std::string>{"all"},
          py::arg("seeds") = StudyOptions{}.seeds, py::arg("rays_per_leaf") = 0,
          py::arg("mesh_rays") = py::none(),
          py::arg("budget_tolerance") = StudyOptions{}.budget_tolerance,
          py::arg("samples") = StudyOptions{}.samples_per_axis, py::arg("progress") = py::none(),
          "`hmcr study` of every oracle x budget x seed, its plots aside; returns its cells");

    m.def("sampling_study", &sampling_study, py::arg("scene"), py::arg("reference"),
          py::arg("output"), py::arg("samplers") = std::vector<std::string>{"all"},
          py::arg("spps") = SamplingStudyOptions{}.spps, py::arg("seeds") = 3, py::arg("seed") = 1,
          py::arg("threads") = 0, py::arg("tree_depth") = TraceOptions{}.tree_depth,
          py::arg("fresh") = false, py::arg("allocation") = "refine",
          py::arg("bounces") = PathOptions{}.max_depth, py::arg("estimator") = "mis",
          py::arg("display_criteria") = false, py::arg("progress") = py::none(),
          "`hmcr study --samplers` of every sampler x spp x seed, its plots aside; its cells");
}

}  // namespace hmcr::python
