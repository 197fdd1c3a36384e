// SPDX-License-Identifier: Apache-2.0
// A solve, and its solution as numpy arrays, its .vtp, its image and its errors.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "python/bindings.h"
#include "python/python_progress.h"
#include "python/values.h"
#include "radiosity/budget_search.h"
#include "radiosity/solver_settings.h"
#include "rays/patch.h"
#include "studies/object_error_json.h"
#include "studies/reference_measure.h"
#include "viz/renderer.h"
#include "viz/solution_file.h"

namespace hmcr::python {
namespace {

using nlohmann::json;

// A solve's result as Python holds it: the solution, its shaded mesh (what the .vtp and the
// arrays hold) and what the file records of the scene.
struct PySolution {
    Solution solution;
    ShadedMesh shaded;
    SceneIdentity scene;
};

// A statistic as Python holds it: a colour as a tuple of its channels.
py::object stat_value(const Rgb& c) { return py::make_tuple(c[0], c[1], c[2]); }
template <class T>
py::object stat_value(const T& v) {
    return py::cast(v);
}

py::dict stats_dict(const SolveStats& stats) {
    py::dict d;
#define HMCR_PY_STAT(type, name, zero, join) d[#name] = stat_value(stats.name);
    HMCR_SOLVE_STATS(HMCR_PY_STAT)
#undef HMCR_PY_STAT
    d["iterations"] = stats.iterations.size();
    std::vector<std::uint64_t> rays;
    for (const IterationRecord& r : stats.iterations) rays.push_back(r.rays);
    d["iteration_rays"] = rays;
    return d;
}

std::unique_ptr<PySolution> solve_scene(const Scene& scene, py::object progress, std::size_t budget,
                                        double budget_tolerance, double crease_degrees,
                                        const py::kwargs& keywords) {
    const SolverOptions options = solve_options(scene, keywords);
    BudgetOptions budget_options;
    budget_options.leaves = budget;
    budget_options.tolerance = budget_tolerance;
    validate(budget_options);
    if (!(crease_degrees >= 0 && crease_degrees <= 180)) {
        throw InputError(
            fmt::format("crease-angle must be in [0, 180] degrees, got {}", crease_degrees));
    }
    auto result = std::make_unique<PySolution>();
    result->scene = scene_identity(scene);
    const SolveInputs inputs{scene.views};
    run_released(std::move(progress), [&](Progress& told) {
        result->solution =
            budget > 0
                ? solve_for_budget(scene.mesh, options, budget_options, inputs, told).solution
                : solve(build_patch_set(scene.mesh), options, inputs, told);
        result->shaded = shade(result->solution, crease_degrees);
    });
    return result;
}

// What `hmcr render SOL.vtp --scene SCENE --pfm` writes, as an array: the solution as its file
// holds it, seen from the scene's view (its first for "").
py::array_t<double> render_solution(const PySolution& s, const Scene& scene,
                                    const std::string& view, int samples) {
    if (samples < 1 || samples > 16) throw InputError("samples must be in 1..16");
    if (s.scene.patches != scene.mesh.n_faces() ||
        s.scene.geometry_hash != geometry_hash(scene.mesh)) {
        throw InputError(fmt::format("the solution is of scene {}, not of {}", quote(s.scene.name),
                                     quote(scene.name)));
    }
    const View& v = find_view(scene, view);
    RenderOptions options;
    options.samples_per_axis = samples;
    const Image image = run_released(
        py::none(), [&](Progress&) { return render(as_stored(s.shaded), v, options); });
    return image_array(image);
}

// What `hmcr error SOL.vtp --reference DIR -o E.json` writes of the solution's metrics: the
// object error with its standard error, each view's RMSE and PSNR, the finer share.
py::object solution_error(const PySolution& s, const std::string& reference, const Scene& scene,
                          int samples) {
    if (samples < 1 || samples > 16) throw InputError("samples must be in 1..16");
    const json out = run_released(py::none(), [&](Progress&) {
        const LoadedReference loaded = load_reference(reference, scene);
        const SolutionErrors e = measure_solution(loaded, as_stored(s.shaded), scene, samples);
        json views = json::object();
        for (const auto& [name, v] : e.views) views[name] = v;
        return json{{"samples_per_axis", samples},
                    {"object_error", object_error_json(e.object)},
                    {"finer_share", e.finer_share},
                    {"views", views}};
    });
    return python_json(out);
}

}  // namespace

void bind_solutions(py::module_& m) {
    py::class_<PySolution>(m, "Solution", "a solve's leaves, values and statistics")
        .def_property_readonly("points", [](const PySolution& s) { return rows3(s.shaded.points); })
        .def_property_readonly("point_radiosity",
                               [](const PySolution& s) { return rows3(s.shaded.point_radiosity); })
        .def_property_readonly("offsets",
                               [](const PySolution& s) { return vector_array(s.shaded.offsets); })
        .def_property_readonly(
            "connectivity", [](const PySolution& s) { return vector_array(s.shaded.connectivity); })
        .def_property_readonly(
            "radiosity", [](const PySolution& s) { return rows3(s.shaded.element_radiosity); })
        .def_property_readonly(
            "area", [](const PySolution& s) { return vector_array(s.shaded.element_area); })
        .def_property_readonly(
            "level", [](const PySolution& s) { return vector_array(s.shaded.hierarchy_level); })
        .def_property_readonly("patch_id",
                               [](const PySolution& s) { return vector_array(s.shaded.patch_id); })
        .def_property_readonly("side",
                               [](const PySolution& s) { return vector_array(s.shaded.side); })
        .def_property_readonly("cluster_id",
                               [](const PySolution& s) -> py::object {
                                   if (s.shaded.cluster_id.empty()) return py::none();
                                   return vector_array(s.shaded.cluster_id);
                               })
        .def_property_readonly(
            "basis", [](const PySolution& s) { return std::string(basis_name(s.shaded.basis)); })
        // A higher-order solution's cells are n x n per leaf: leaf_index says whose, None on the
        // constant basis (one cell per leaf).
        .def_property_readonly("leaf_index",
                               [](const PySolution& s) -> py::object {
                                   if (s.shaded.leaf_index.empty()) return py::none();
                                   return vector_array(s.shaded.leaf_index);
                               })
        .def_property_readonly("leaf_coordinates",
                               [](const PySolution& s) -> py::object {
                                   const auto& ab = s.shaded.leaf_coordinates;
                                   if (ab.empty()) return py::none();
                                   py::array_t<double> a({py::ssize_t(ab.size()), py::ssize_t(2)});
                                   auto out = a.mutable_unchecked<2>();
                                   for (std::size_t i = 0; i < ab.size(); ++i) {
                                       out(py::ssize_t(i), 0) = ab[i].x();
                                       out(py::ssize_t(i), 1) = ab[i].y();
                                   }
                                   return a;
                               })
        // Per cell its leaf's K x 3 coefficients: shape (cells, K, 3).
        .def_property_readonly(
            "coefficients",
            [](const PySolution& s) -> py::object {
                const ShadedMesh& shaded = s.shaded;
                if (shaded.coefficients.empty()) return py::none();
                py::array_t<double> a({py::ssize_t(shaded.cell_count()),
                                       py::ssize_t(basis_size(shaded.basis)), py::ssize_t(3)});
                std::copy(shaded.coefficients.begin(), shaded.coefficients.end(), a.mutable_data());
                return a;
            })
        .def_property_readonly("stats",
                               [](const PySolution& s) { return stats_dict(s.solution.stats); })
        .def_property_readonly(
            "options",
            [](const PySolution& s) { return python_json(settings_json(s.solution.options)); })
        .def(
            "information",
            [](const PySolution& s, std::uint64_t lines, const std::string& method,
               std::uint64_t seed, py::object progress) {
                return channel_information(leaf_states(as_stored(s.shaded)), lines, method, seed,
                                           std::move(progress));
            },
            py::arg("lines") = LineOptions{}.lines, py::arg("method") = "local",
            py::arg("seed") = LineOptions{}.seed, py::arg("progress") = py::none(),
            "`hmcr info SOLUTION.vtp --json`: the measures of the channel of its leaves")
        .def("render", &render_solution, py::arg("scene"), py::arg("view") = "",
             py::arg("samples") = 1,
             "the linear radiance image of the solution from a view of its scene (H x W x 3)")
        .def(
            "write_vtp",
            [](const PySolution& s, const std::string& path) {
                const py::gil_scoped_release released;
                write_solution(path, s.shaded, s.solution, s.scene,
                               double(s.solution.stats.iterations.size()));
            },
            py::arg("path"), "the .vtp `hmcr solve` writes for the same scene and settings");

    m.def("solve", &solve_scene, py::arg("scene"), py::arg("progress") = py::none(),
          py::arg("budget") = 0, py::arg("budget_tolerance") = BudgetOptions{}.tolerance,
          py::arg("crease_angle") = kCreaseDegrees,
          "solves the scene; every solver setting is a keyword (hmcr.settings())");

    m.def("error", &solution_error, py::arg("solution"), py::arg("reference"), py::arg("scene"),
          py::arg("samples") = 2,
          "a study's metrics for the solution against the reference folder (`hmcr error`)");

    m.def(
        "settings",
        [] {
            py::list out;
            const json defaults = settings_json(SolverOptions{});
            for_each_setting([&](const auto& setting) {
                if (setting.scope == SettingScope::internal) return;
                py::dict d;
                d["name"] = std::string(setting.name);
                d["scope"] =
                    setting.scope == SettingScope::scene_file ? "scene_file" : "command_line";
                d["default"] = python_json(defaults.at(std::string(setting.name)));
                d["range"] = setting.range;
                d["help"] = std::string(setting.help);
                out.append(d);
            });
            return out;
        },
        "every solver setting: name, scope, default, range and help, from the one settings table");
}

}  // namespace hmcr::python
