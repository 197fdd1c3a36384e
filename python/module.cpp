// SPDX-License-Identifier: Apache-2.0
// The Python module hmcr._core (docs/python.md): scenes from files and from arrays, a solve with
// every solver setting as a keyword, and its solution as numpy arrays and as the .vtp the command
// line writes. hmcr works with the GIL released; progress calls back into Python between ray
// batches, where Ctrl-C stops the work.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <xmmintrin.h>

#include <csignal>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/run_summary.h"
#include "app/trace_flags.h"
#include "common/interrupt.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "common/progress.h"
#include "information/back_sides.h"
#include "information/scene_information.h"
#include "meshes/polygon_soup.h"
#include "radiosity/budget_search.h"
#include "radiosity/solver_settings.h"
#include "rays/patch.h"
#include "studies/object_error_json.h"
#include "studies/point_reference.h"
#include "studies/reference.h"
#include "studies/reference_measure.h"
#include "studies/sampling_study.h"
#include "studies/study.h"
#include "trace/criteria/registry.h"
#include "trace/path_tracer.h"
#include "viz/renderer.h"
#include "viz/solution_file.h"

namespace py = pybind11;

namespace hmcr {
namespace {

using nlohmann::json;

// Progress told to a Python callable, callback(stage, fraction), with Python's signals checked
// at each call: an exception there (KeyboardInterrupt from Ctrl-C, or the callback's own) stops
// the work at its next safe point as Interrupted does on the command line, and is raised again
// once the work has unwound.
class PythonProgress final : public Progress {
public:
    explicit PythonProgress(py::object callback) : m_callback(std::move(callback)) {}
    void stage(std::string_view label) override {
        m_stage = label;
        call(0);
    }
    void advance(double fraction) override { call(fraction); }
    void note(std::string_view) override {}

    // With the GIL held: raises the Python exception that stopped the work, if one did.
    void raise_if_stopped() {
        if (!m_error) return;
        m_error->restore();
        m_error.reset();
        throw py::error_already_set();
    }

private:
    void call(double fraction) {
        const py::gil_scoped_acquire gil;
        try {
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (!m_callback.is_none()) m_callback(m_stage, fraction);
        } catch (py::error_already_set& e) {
            m_error.emplace(std::move(e));
            throw Interrupted(SIGINT);
        }
    }

    py::object m_callback;
    std::string m_stage;
    std::optional<py::error_already_set> m_error;
};

// The caller's floating-point mode, given back when a call ends: hmcr's tracing flushes
// subnormal numbers to zero in the threads that trace (rays/embree_scene.h), the caller's among
// them, and Python's own arithmetic (numpy's) must not inherit that.
class CallersFloatMode {
public:
    CallersFloatMode() : m_csr(_mm_getcsr()) {}
    ~CallersFloatMode() { _mm_setcsr(m_csr); }
    CallersFloatMode(const CallersFloatMode&) = delete;
    CallersFloatMode& operator=(const CallersFloatMode&) = delete;

private:
    unsigned m_csr;
};

// A keyword's value as the JSON a scene file's "solver" object would hold.
json keyword_json(const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) {
        const py::int_ i = value.cast<py::int_>();
        if (i < py::int_(0)) return value.cast<std::int64_t>();
        return value.cast<std::uint64_t>();
    }
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    throw InputError(fmt::format("a setting must be a number or a string, got a {}",
                                 std::string(py::str(value.get_type().attr("__name__")))));
}

// The options of a solve of `scene`: `base`, then the scene file's "solver" object but for the
// keys in `not_from_scene`, then the keywords, as `hmcr solve` takes its flags over the scene
// file.
SolverOptions solve_options(const Scene& scene, const py::kwargs& keywords, SolverOptions base = {},
                            const std::set<std::string>& not_from_scene = {}) {
    json from_scene = scene.solver_defaults;
    for (const std::string& key : not_from_scene) from_scene.erase(key);
    apply_scene_settings(from_scene, scene.source.string(), base);
    json values = json::object();
    for (const auto& [key, value] : keywords) values[py::str(key)] = keyword_json(value);
    apply_settings(values, base);
    validate(base);
    return base;
}

// A solve's result as Python holds it: the solution, its shaded mesh (what the .vtp and the
// arrays hold) and what the file records of the scene.
struct PySolution {
    Solution solution;
    ShadedMesh shaded;
    SceneIdentity scene;
};

template <class T>
py::array_t<T> vector_array(const std::vector<T>& v) {
    return py::array_t<T>(py::ssize_t(v.size()), v.data());
}

// An N x 3 array of the vectors or colours.
template <class V>
py::array_t<double> rows3(const std::vector<V>& v) {
    py::array_t<double> a({py::ssize_t(v.size()), py::ssize_t(3)});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < v.size(); ++i) {
        for (int c = 0; c < 3; ++c) m(py::ssize_t(i), c) = v[i][c];
    }
    return a;
}

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
    PythonProgress told(std::move(progress));
    const CallersFloatMode mode;
    try {
        const py::gil_scoped_release released;
        result->solution =
            budget > 0
                ? solve_for_budget(scene.mesh, options, budget_options, inputs, told).solution
                : solve(build_patch_set(scene.mesh), options, inputs, told);
        result->shaded = shade(result->solution, crease_degrees);
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    return result;
}

py::object python_json(const json& j) {
    return py::module_::import("json").attr("loads")(j.dump());
}

// An image as an H x W x 3 array of linear radiance, W sr^-1 m^-2, the top row first.
py::array_t<double> image_array(const Image& image) {
    py::array_t<double> a({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
    auto m = a.mutable_unchecked<3>();
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) m(y, x, c) = image.at(x, y)[c];
        }
    }
    return a;
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
    Image image;
    {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        image = render(as_stored(s.shaded), v, options);
    }
    return image_array(image);
}

// What `hmcr error SOL.vtp --reference DIR -o E.json` writes of the solution's metrics: the
// object error with its standard error, each view's RMSE and PSNR, the finer share.
py::object solution_error(const PySolution& s, const std::string& reference, const Scene& scene,
                          int samples) {
    if (samples < 1 || samples > 16) throw InputError("samples must be in 1..16");
    json out;
    {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        const LoadedReference loaded = load_reference(reference, scene);
        const SolutionErrors e = measure_solution(loaded, as_stored(s.shaded), scene, samples);
        json views = json::object();
        for (const auto& [name, v] : e.views) views[name] = v;
        out = {{"samples_per_axis", samples},
               {"object_error", object_error_json(e.object)},
               {"finer_share", e.finer_share},
               {"views", views}};
    }
    return python_json(out);
}

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
    PythonProgress told(std::move(progress));
    std::optional<Reference> ref;
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        ref.emplace(compute_reference(scene, o, told));
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    RunTimings timings;
    timings.total_seconds = ref->seconds;
    write_reference(out, dir, scene, *ref, o,
                    run_summary(scene, ref->solution, timings, "python: hmcr.mesh_reference",
                                (dir / "reference.vtp").string()));
    out.commit();
    return python_json(
        {{"leaves", ref->solution.stats.leaves},
         {"seconds", ref->seconds},
         {"seed_difference", object_error_json(ref->object_error)},
         {"truncation",
          {ref->truncation.relative[0], ref->truncation.relative[1], ref->truncation.relative[2]}},
         {"discretisation", object_error_json(ref->discretisation)}});
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
    if (!oracles.empty()) {
        o.oracles.clear();
        for (const std::string& name : oracles) {
            const Oracle* oracle = oracle_registry().find(name);
            if (!oracle) {
                throw InputError(fmt::format("oracles: {} is none of {}", quote(name),
                                             oracle_registry().names()));
            }
            o.oracles.push_back(oracle);
        }
    }
    o.seeds = seeds;
    o.rays_per_leaf = rays_per_leaf;
    o.mesh_rays = mesh_rays;
    o.budget_tolerance = budget_tolerance;
    o.samples_per_axis = samples;
    o.solver = solve_options(scene, keywords);
    validate_study(o);
    refuse_nested_dirs(o.output, o.reference);
    refuse_overwriting(study_output_files(scene, o), scene.inputs);
    PythonProgress told(std::move(progress));
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        run_study(scene, o, told);
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    return study_cells(output);
}

// `hmcr info SCENE --json` (patches) or `hmcr info SOLUTION.vtp --json` (leaves): the entropies
// and mutual information of the channel whose states are `states`.
py::object information(const ChannelStates& states, std::uint64_t lines, const std::string& method,
                       std::uint64_t seed, py::object progress) {
    if (lines < 16) throw InputError("lines must be at least 16");
    LineOptions o;
    o.method = parse_line_method(method);
    o.lines = lines;
    o.seed = seed;
    PythonProgress told(std::move(progress));
    std::optional<InformationMeasures> m;
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        m.emplace(scene_information(states, o, told));
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    json j = to_json(*m);
    j["open_fraction"] = double(m->samples_open) / double(std::max<std::size_t>(1, m->samples));
    return python_json(j);
}

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
    o.sampler = criterion_registry().find(sampler);
    if (!o.sampler) {
        throw InputError(fmt::format("sampler must be one of {}, got {}",
                                     criterion_registry().names(), quote(sampler)));
    }
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
    PythonProgress told(std::move(progress));
    std::optional<TraceResult> r;
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        const PathTracer tracer(build_patch_set(scene.mesh), o.path);
        r.emplace(trace_image(tracer, v, o, told));
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    py::array_t<std::uint32_t> samples({py::ssize_t(v.height), py::ssize_t(v.width)});
    std::copy(r->samples.begin(), r->samples.end(), samples.mutable_data());
    py::dict d;
    d["image"] = image_array(r->image);
    d["samples"] = samples;
    d["threshold"] = r->threshold;
    d["rays"] = r->rays;
    d["seconds"] = r->seconds;
    return d;
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
    PythonProgress told(std::move(progress));
    std::optional<PointReference> ref;
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        ref.emplace(compute_point_reference(sized, o, told));
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    write_point_reference(out, dir, sized, *ref, o, "python: hmcr.points_reference");
    out.commit();
    const PointReferenceReport& r = ref->report;
    return python_json({{"points", ref->points.points.size()},
                        {"area_per_point", r.area_per_point},
                        {"noise", r.noise},
                        {"seed_check", r.seed_check},
                        {"seed_check_se", r.seed_check_se},
                        {"rays", r.rays},
                        {"seconds", ref->seconds}});
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
    if (!samplers.empty()) {
        o.samplers.clear();
        for (const std::string& name : samplers) {
            const Criterion* c = criterion_registry().find(name);
            if (!c) {
                throw InputError(fmt::format("samplers: {} is none of {}", quote(name),
                                             criterion_registry().names()));
            }
            o.samplers.push_back(c);
        }
    }
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
    PythonProgress told(std::move(progress));
    try {
        const CallersFloatMode mode;
        const py::gil_scoped_release released;
        run_sampling_study(scene, o, told);
    } catch (const Interrupted&) {
        told.raise_if_stopped();
        throw;
    }
    return study_cells(output);
}

// The polygons of arrays as a soup of one file, "<arrays>", whose items are faces: a face's
// problem is reported as "<arrays>: face N" (1-based).
PolygonSoup arrays_soup(const py::array_t<double, py::array::c_style | py::array::forcecast>& v,
                        const py::sequence& faces,
                        const py::array_t<double, py::array::c_style | py::array::forcecast>& rho,
                        const py::array_t<double, py::array::c_style | py::array::forcecast>& e,
                        int sides) {
    if (v.ndim() != 2 || v.shape(1) != 3) throw InputError("vertices must be an N x 3 array");
    const auto per_face = [&](const auto& a, const char* what) {
        const bool one = a.ndim() == 1 && a.shape(0) == 3;
        if (!one &&
            !(a.ndim() == 2 && a.shape(1) == 3 && a.shape(0) == py::ssize_t(py::len(faces)))) {
            throw InputError(fmt::format("{} must be 3 values or one row of 3 per face", what));
        }
        return one;
    };
    const bool one_rho = per_face(rho, "reflectance"), one_e = per_face(e, "emission");
    if (sides != 1 && sides != 2)
        throw InputError(fmt::format("sides must be 1 or 2, got {}", sides));
    PolygonSoup soup;
    soup.files.emplace_back("<arrays>");
    soup.item_names[0] = "face";
    const auto vertices = v.unchecked<2>();
    for (py::ssize_t i = 0; i < vertices.shape(0); ++i)
        soup.positions.emplace_back(vertices(i, 0), vertices(i, 1), vertices(i, 2));
    const auto colour = [](const auto& a, bool one, std::size_t f) {
        const double* p = a.data() + (one ? 0 : 3 * f);
        return Eigen::Vector3d(p[0], p[1], p[2]);
    };
    std::size_t f = 0;
    for (const py::handle face : faces) {
        const SourcePlace at{0, std::uint32_t(f + 1)};
        std::vector<std::uint32_t> ids;
        for (const py::handle corner : face.cast<py::sequence>()) {
            const auto id = corner.cast<std::int64_t>();
            if (id < 0 || id >= std::int64_t(soup.positions.size())) {
                throw InputError(soup.where(at), fmt::format("corner {} is not a vertex (0 to {})",
                                                             id, soup.positions.size() - 1));
            }
            ids.push_back(std::uint32_t(id));
        }
        SoupMaterial m;
        m.material.name = fmt::format("face {}", f + 1);
        m.material.kd = colour(rho, one_rho, f);
        m.material.ke = colour(e, one_e, f) / std::numbers::pi;  // E = pi Ke
        m.kd = m.ke = m.ks = at;
        m.sides = sides;
        soup.materials.push_back(m);
        soup.add_polygon(ids, std::int32_t(f), at);
        ++f;
    }
    return soup;
}

}  // namespace
}  // namespace hmcr

PYBIND11_MODULE(_core, m) {
    using namespace hmcr;
    m.doc() = "hmcr's engine: scenes, solves and solutions (docs/python.md)";
    m.attr("__version__") = HMCR_VERSION;
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

    py::class_<Scene>(m, "Scene", "a scene as loaded: its patches, materials and views")
        .def_readonly("name", &Scene::name)
        .def_property_readonly("patch_count",
                               [](const Scene& s) { return std::size_t(s.mesh.n_faces()); })
        .def_readonly("warnings", &Scene::warnings)
        .def_property_readonly("views", [](const Scene& s) {
            std::vector<std::string> names;
            for (const View& v : s.views) names.push_back(v.name);
            return names;
        });

    m.def(
        "load_scene",
        [](const std::string& name_or_path, bool strict, int sides) {
            LoadOptions options;
            options.strict = strict;
            if (sides != 0) options.sides = sides;
            const py::gil_scoped_release released;
            return new Scene(load_scene(name_or_path, options));
        },
        py::arg("scene"), py::arg("strict") = false, py::arg("sides") = 0,
        "a bundled scene's name, a scene .json or a mesh file, loaded as `hmcr solve` loads it");

    m.def(
        "scene_from_arrays",
        [](const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
           const py::sequence& faces,
           const py::array_t<double, py::array::c_style | py::array::forcecast>& reflectance,
           const py::array_t<double, py::array::c_style | py::array::forcecast>& emission,
           int sides, const std::string& name, bool strict, const py::object& views) {
            PolygonSoup soup = arrays_soup(vertices, faces, reflectance, emission, sides);
            std::vector<View> given;
            if (!views.is_none()) {  // as a scene file's "views" array
                const std::string text = py::str(py::module_::import("json").attr("dumps")(views));
                given = read_views(json::parse(text), "<arrays>");
            }
            LoadOptions options;
            options.strict = strict;
            std::unique_ptr<Scene> scene;
            {
                const py::gil_scoped_release released;
                scene.reset(new Scene(load_soup_scene(name, std::move(soup), options)));
            }
            if (!given.empty()) {
                scene->views = std::move(given);
                scene->default_views = false;
            }
            return scene;
        },
        py::arg("vertices"), py::arg("faces"), py::arg("reflectance"), py::arg("emission"),
        py::arg("sides") = 2, py::arg("name") = "arrays", py::arg("strict") = false,
        py::arg("views") = py::none(),
        "a scene of polygons given as arrays; views as a scene file's \"views\" (a list of "
        "dicts), else the default view");

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
        .def_property_readonly("stats",
                               [](const PySolution& s) { return stats_dict(s.solution.stats); })
        .def_property_readonly(
            "options",
            [](const PySolution& s) { return python_json(settings_json(s.solution.options)); })
        .def(
            "information",
            [](const PySolution& s, std::uint64_t lines, const std::string& method,
               std::uint64_t seed, py::object progress) {
                return information(leaf_states(as_stored(s.shaded)), lines, method, seed,
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

    m.def("mesh_reference", &mesh_reference, py::arg("scene"), py::arg("output"),
          py::arg("max_area") = ReferenceOptions{}.max_area,
          py::arg("samples") = ReferenceOptions{}.samples_per_axis,
          py::arg("check_points") = py::none(), py::arg("progress") = py::none(),
          "`hmcr reference --kind mesh`: a converged uniform-mesh reference in a folder");

    m.def(
        "information",
        [](const Scene& scene, std::uint64_t lines, const std::string& method, std::uint64_t seed,
           py::object progress) {
            return information(patch_states(build_patch_set(scene.mesh)), lines, method, seed,
                               std::move(progress));
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

    m.def("points_reference", &points_reference, py::arg("scene"), py::arg("output"),
          py::arg("points") = PointReferenceOptions{}.points,
          py::arg("paths") = PointReferenceOptions{}.paths, py::arg("seed") = 1,
          py::arg("strata_seed") = 0, py::arg("threads") = 0,
          py::arg("spp") = PointReferenceOptions{}.views.spp,
          py::arg("bounces") = PathOptions{}.max_depth, py::arg("estimator") = "mis",
          py::arg("width") = py::none(), py::arg("progress") = py::none(),
          "`hmcr reference --kind points`: radiosity at stratified points, path-traced");
    m.def("sampling_study", &sampling_study, py::arg("scene"), py::arg("reference"),
          py::arg("output"), py::arg("samplers") = std::vector<std::string>{},
          py::arg("spps") = SamplingStudyOptions{}.spps, py::arg("seeds") = 3, py::arg("seed") = 1,
          py::arg("threads") = 0, py::arg("tree_depth") = TraceOptions{}.tree_depth,
          py::arg("fresh") = false, py::arg("allocation") = "refine",
          py::arg("bounces") = PathOptions{}.max_depth, py::arg("estimator") = "mis",
          py::arg("display_criteria") = false, py::arg("progress") = py::none(),
          "`hmcr study --samplers` of every sampler x spp x seed, its plots aside; its cells");

    m.def("meshing_study", &meshing_study, py::arg("scene"), py::arg("reference"),
          py::arg("budgets"), py::arg("output"), py::arg("oracles") = std::vector<std::string>{},
          py::arg("seeds") = StudyOptions{}.seeds, py::arg("rays_per_leaf") = 0,
          py::arg("mesh_rays") = py::none(),
          py::arg("budget_tolerance") = StudyOptions{}.budget_tolerance,
          py::arg("samples") = StudyOptions{}.samples_per_axis, py::arg("progress") = py::none(),
          "`hmcr study` of every oracle x budget x seed, its plots aside; returns its cells");

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
