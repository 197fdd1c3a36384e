// SPDX-License-Identifier: Apache-2.0
#include "studies/study.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

#include "common/file_names.h"
#include "common/hash.h"
#include "common/output_set.h"
#include "common/stopwatch.h"
#include "common/text_file.h"
#include "common/version.h"
#include "image/image.h"
#include "meshes/scene.h"
#include "radiosity/oracle_registry.h"
#include "radiosity/solver_settings.h"
#include "rays/patch.h"
#include "studies/cell_handout.h"
#include "studies/plot_data.h"
#include "studies/reference_measure.h"
#include "studies/study_figures.h"
#include "studies/traced_reference.h"
#include "viz/renderer.h"
#include "viz/shaded_tracer.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

using Clock = std::chrono::steady_clock;

// "study: budget 500 is given twice".
template <class T>
void refuse_repeats(const std::vector<T>& values, const char* what) {
    std::set<T> seen;  // n log n: a study may list a thousand
    for (const T& v : values) {
        if (!seen.insert(v).second)
            throw InputError(fmt::format("study: {} {} is given twice", what, v));
    }
}

void validate(const StudyOptions& o) {
    if (o.budgets.empty()) throw InputError("study: no budget given");
    if (o.oracles.empty()) throw InputError("study: no oracle given");
    if (o.seeds < 1) throw InputError("study: seeds must be at least 1");
    if (!(o.budget_tolerance > 0 && o.budget_tolerance < 1)) {
        throw InputError(
            fmt::format("study: budget-tolerance {:g} is not in (0, 1)", o.budget_tolerance));
    }
    check_study_size(std::uint64_t(o.budgets.size()) * o.oracles.size(), o.seeds, o.solver.seed);
    refuse_repeats(o.budgets, "budget");
    if (o.budgets.size() > kMaxPlotPoints) {
        throw InputError(fmt::format("study: {} budgets; at most {}, the points a plot shows",
                                     o.budgets.size(), kMaxPlotPoints));
    }
    std::vector<std::string_view> names;
    for (const Oracle* oracle : o.oracles) names.push_back(oracle->name());
    refuse_repeats(names, "oracle");
    if (o.output.empty()) throw InputError("study: no output folder given");
    chosen_columns(o.columns, study_table_columns(), "meshing");
    validate(o.solver);
    for (std::size_t b : o.budgets) {
        // Each product is checked against the limit before it is formed (no wrap-around).
        if (o.rays_per_leaf > kMaxRays / b ||
            (cell_rays(o, b) > kMaxRays / kMeshRaysPerCellRay && !o.mesh_rays)) {
            throw InputError(fmt::format("study: budget {} would shoot more than 1e15 rays", b));
        }
    }
}

// One cell to run, and where its result lives.
struct MeshingCell {
    const Oracle* oracle = nullptr;
    std::size_t budget = 0;
    std::uint64_t seed = 0;
    std::string name;
};

class StudyRunner {
public:
    StudyRunner(const Scene& scene, const StudyOptions& o, Progress& progress)
        : m_options(o), m_progress(progress), m_scene(scene) {
        validate(o);
        check_root_count(scene.mesh.n_faces(), element_limit(o.solver));  // before any cell
        for (std::size_t b : o.budgets)
            for (const Oracle* oracle : o.oracles)
                for (int s = 0; s < o.seeds; ++s) {
                    const std::uint64_t seed = o.solver.seed + std::uint64_t(s);
                    m_tasks.push_back(
                        {oracle, b, seed,
                         cell_name(m_scene.name, std::string(oracle->name()), b, seed)});
                }
        // Rank 0 writes the tables: it alone checks, locks and holds them, before any work;
        // every rank learns of a refusal.
        together(Ranks::world(), [&] {
            if (Ranks::world().root()) m_tables.emplace(study_output_files(scene, o), o.output);
        });
        m_settings = study_settings(m_scene, m_options);
    }

    void run();

private:
    std::optional<CellResult> previous_cell(std::size_t index);
    std::string lacks(const CellResult& cell, const MeshingCell& t) const;
    std::filesystem::path cell_file(const MeshingCell& t) const {
        return named_file(m_options.output / "cells", t.name, ".json");
    }
    // NAME.vtp and NAME-VIEW.png of a cell's solution (NAME: the cell's name) or of its frozen
    // re-solve (NAME-mesh).
    std::filesystem::path mesh_file(const std::string& name) const {
        return named_file(m_options.output / "meshes", name, ".vtp");
    }
    std::filesystem::path image_file(const std::string& name, const View& view) const {
        return named_file(m_options.output / "images", name + "-" + view.name, ".png");
    }
    std::vector<std::filesystem::path> outputs(std::size_t index) const;
    CellResult compute(std::size_t index, FileBatch& files);
    ObjectError measure(const Solution& solution, const MeshingCell& t, const std::string& name,
                        std::map<std::string, ImageErrors>& views, FileBatch& files,
                        double* finer_share = nullptr);
    void check_resolution(const CellResult& cell, CellNotes& notes) const;
    std::string where(std::size_t index) const;

    const StudyOptions& m_options;
    Progress& m_progress;
    const Scene& m_scene;
    std::vector<MeshingCell> m_tasks;
    nlohmann::json m_settings;
    LoadedReference m_reference;
    std::optional<OutputSet> m_tables;  // rank 0's
    // The probes this rank has solved, by oracle, seed and rays: the cells of the other budgets
    // search from the same start (radiosity/budget_search.h). Which cells a rank solved changes
    // how long a cell takes, never its result. Not filled from the cells a resumed study reads
    // back: those may come from another build, whose solves need not give these bits.
    std::map<std::tuple<std::string, std::uint64_t, std::uint64_t>, KnownProbes> m_known;
};

std::string StudyRunner::where(std::size_t index) const {
    return fmt::format("[{}/{}] {}", index + 1, m_tasks.size(), m_tasks[index].name);
}

std::optional<CellResult> StudyRunner::previous_cell(std::size_t index) {
    const MeshingCell& t = m_tasks[index];
    CellFileRule<CellResult> rule;
    rule.parse = [](const nlohmann::json& j) { return cell_from_json(j); };
    rule.is_this_cell = [&](const CellResult& c) {
        return c.scene == m_scene.name && c.oracle == t.oracle->name() && c.budget == t.budget &&
               c.seed == t.seed;
    };
    rule.settings = m_settings;
    rule.redo_other_settings = m_options.redo_other_settings;
    rule.lacks = [&](const CellResult& c) { return lacks(c, t); };
    CellNotes notes(m_progress, where(index) + ": ");
    return read_previous_cell<CellResult>(cell_file(t), rule, notes);
}

// What an earlier cell of the same settings lacks: a result for every view, and the rays and
// mesh error these settings give a cell (a failed cell has none).
std::string StudyRunner::lacks(const CellResult& c, const MeshingCell& t) const {
    if (!c.ok()) return "";
    std::vector<std::string> views;
    for (const View& v : m_scene.views) views.push_back(v.name);
    const std::uint64_t rays = cell_rays(m_options, t.budget);
    const std::uint64_t mesh_rays = cell_mesh_rays(m_options, t.budget);
    if (c.rays != rays) return fmt::format("rays {}, not the {} of this cell", c.rays, rays);
    if (c.mesh_rays != mesh_rays) {
        return fmt::format("mesh_rays {}, not the {} of this cell", c.mesh_rays, mesh_rays);
    }
    if (std::string m = missing_view(c.views, views); !m.empty()) return m;
    return mesh_rays > 0 ? missing_view(c.mesh_views, views, "mesh error") : "";
}

// Every file a cell writes, for the checks before any cell is computed.
std::vector<std::filesystem::path> StudyRunner::outputs(std::size_t index) const {
    const MeshingCell& t = m_tasks[index];
    std::vector<std::string> names{t.name};
    if (cell_mesh_rays(m_options, t.budget) > 0) names.push_back(t.name + "-mesh");
    std::vector<std::filesystem::path> files{cell_file(t)};
    for (const std::string& name : names) {
        files.push_back(mesh_file(name));
        for (const View& v : m_scene.views) files.push_back(image_file(name, v));
    }
    return files;
}

void StudyRunner::run() {
    m_reference = load_reference(m_options.reference, m_scene);
    CellLoop<CellResult> loop;
    loop.count = m_tasks.size();
    loop.previous = [this](std::size_t i) { return previous_cell(i); };
    loop.compute = [this](std::size_t i, FileBatch& files) { return compute(i, files); };
    loop.to_json = cell_to_json;
    loop.from_json = cell_from_json;
    loop.file = [this](std::size_t i) { return cell_file(m_tasks[i]); };
    loop.outputs = [this](std::size_t i) { return outputs(i); };
    loop.where = [this](std::size_t i) { return where(i); };
    loop.outcome = [](const CellResult& c) {
        return c.ok() ? "done" : "budget not reached, recorded as failed";
    };
    const std::vector<CellResult> cells = run_cells_on(Ranks::world(), loop, m_progress);
    if (!Ranks::world().root()) return;  // rank 0 writes the tables
    std::vector<std::string> views;
    for (const View& v : m_scene.views) views.push_back(v.name);
    write_study_tables(*m_tables, m_scene.name, m_options, views, cells);
    write_study_figures(*m_tables, m_scene, m_options, cells, m_reference.images);
    m_tables->commit();
    for (std::size_t b : m_options.budgets) {
        if (const std::string w = finer_warning(cells, b); !w.empty()) {
            m_progress.note(fmt::format("warning: at {} leaves, {}", b, w));
        }
    }
}

CellResult StudyRunner::compute(std::size_t index, FileBatch& files) {
    const MeshingCell& t = m_tasks[index];
    CellResult cell;
    cell.settings = m_settings;
    cell.scene = m_scene.name;
    cell.oracle = t.oracle->name();
    cell.budget = t.budget;
    cell.seed = t.seed;
    SolverOptions so = m_options.solver;
    so.oracle = t.oracle;
    so.epsilon = kOracleDefault;
    so.seed = t.seed;
    so.rays = cell.rays = cell_rays(m_options, t.budget);
    CellNotes notes(m_progress, where(index) + ": ");
    const auto start = Clock::now();
    try {
        const BudgetResult r = solve_for_budget(
            m_scene.mesh, so, {t.budget, m_options.budget_tolerance}, {m_scene.views}, notes,
            Ranks::single(), &m_known[{cell.oracle, cell.seed, cell.rays}]);
        cell.seconds = seconds_since(start);
        cell.probes = r.probes;
        cell.epsilon = r.solution.stats.epsilon;
        cell.leaves = r.solution.stats.leaves;
        notes.note("rendering and measuring");
        cell.object_error = measure(r.solution, t, t.name, cell.views, files, &cell.finer_share);
        check_resolution(cell, notes);
        cell.mesh_rays = cell_mesh_rays(m_options, t.budget);
        if (cell.mesh_rays > 0) {
            notes.note(fmt::format("mesh error: the mesh frozen, {} rays", cell.mesh_rays));
            so.rays = cell.mesh_rays;
            const Solution frozen = solve_on_mesh(m_scene.mesh, so, r.solution);
            cell.mesh_object_error = measure(frozen, t, t.name + "-mesh", cell.mesh_views, files);
        }
    } catch (const BudgetNotReached& e) {
        cell.seconds = seconds_since(start);
        cell.status = "failed";
        cell.message = e.what();
    }
    return cell;
}

// A cell whose leaves are finer than the reference resolves: a note, or with --strict a refusal
// (the cell is not kept: its errors would have a floor the reference sets).
void StudyRunner::check_resolution(const CellResult& cell, CellNotes& notes) const {
    if (!(cell.finer_share > kFinerShareLimit)) return;
    const std::string what = fmt::format(
        "{:.0f}% of the area is in leaves finer than the reference resolves (more than {:.0f}%): "
        "its errors are bounded below by the reference's; make a finer one (hmcr reference "
        "--for-budget {})",
        100 * cell.finer_share, 100 * kFinerShareLimit, cell.budget);
    if (m_options.strict)
        throw InputError(cell_name(cell.scene, cell.oracle, cell.budget, cell.seed) + ": " + what);
    notes.note("warning: " + what);
}

// The mesh file NAME.vtp, the images NAME-VIEW.png (into the cell's batch) and the metrics of a
// solution: the image errors of every view into `views`, the object-space error returned.
ObjectError StudyRunner::measure(const Solution& solution, const MeshingCell& t,
                                 const std::string& name, std::map<std::string, ImageErrors>& views,
                                 FileBatch& files, double* finer_share) {
    const ShadedMesh mesh = write_solution(files.temp(mesh_file(name)), solution, m_scene,
                                           m_options.crease_degrees, double(t.budget));
    SolutionErrors e = measure_solution(m_reference, mesh, m_scene, m_options.samples_per_axis);
    for (const View& v : m_scene.views)
        write_png(files.temp(image_file(name, v)), e.images.at(v.name));
    views = std::move(e.views);
    if (finer_share) *finer_share = e.finer_share;
    return e.object;
}

// The repairs as a cell records them: each kind's first place as FILE:LINE without the folder,
// so that a study resumes from any working folder and with absolute or relative scene paths
// alike (the geometry hash says the scene is the same).
nlohmann::json portable_repairs(nlohmann::json repairs) {
    for (auto& [kind, value] : repairs.items()) {
        if (!value.is_object() || !value.contains("first")) continue;
        const std::string first = value["first"].get<std::string>();
        value["first"] = std::filesystem::path(first).filename().string();
    }
    return repairs;
}

}  // namespace

void validate_study(const StudyOptions& options) { validate(options); }

nlohmann::json study_settings(const Scene& scene, const StudyOptions& o) {
    nlohmann::json solve = settings_json(o.solver);
    for (const char* per_cell_or_no_effect :
         {"oracle", "epsilon", "seed", "threads", "cache_mb", "uniform_max_area"}) {
        solve.erase(per_cell_or_no_effect);
    }
    const std::string reference_json = read_text_file(o.reference / "reference.json");
    return {{"scene", scene.name},
            // A version that gives other bits makes other cells.
            {"bits_version", std::string(bits_version())},
            {"rays_per_leaf", o.rays_per_leaf},
            {"mesh_rays", mesh_rays_json(o)},
            {"geometry", geometry_hash(scene.mesh)},
            // Whether the scene was repaired (a strict load of it would be refused) and how.
            {"repaired", !scene.repairs.empty()},
            {"repairs", portable_repairs(scene.repairs.to_json())},
            {"reference_json_hash", text_hash(reference_json)},
            {"solve", solve},
            {"budget_tolerance", o.budget_tolerance},
            {"samples_per_axis", o.samples_per_axis},
            {"crease_degrees", o.crease_degrees}};
}

std::uint64_t cell_rays(const StudyOptions& o, std::size_t budget) {
    return o.rays_per_leaf > 0 ? o.rays_per_leaf * budget : o.solver.rays;
}

std::uint64_t cell_mesh_rays(const StudyOptions& o, std::size_t budget) {
    return o.mesh_rays ? *o.mesh_rays : kMeshRaysPerCellRay * cell_rays(o, budget);
}

nlohmann::json mesh_rays_json(const StudyOptions& o) {
    if (o.mesh_rays) return *o.mesh_rays;
    return std::to_string(kMeshRaysPerCellRay) + "x";
}

std::string cell_name(const std::string& scene, const std::string& oracle, std::size_t budget,
                      std::uint64_t seed) {
    return fmt::format("{}-{}-B{}-s{}", scene, oracle, budget, seed);
}

std::vector<std::filesystem::path> study_table_files(const StudyOptions& o) {
    return {o.output / "table.json", o.output / "table.csv", o.output / "patches.csv",
            o.output / "table.md",   o.output / "table.tex", plot_data_file(o.output)};
}

std::vector<std::filesystem::path> study_output_files(const Scene& scene, const StudyOptions& o) {
    std::vector<std::filesystem::path> files = study_table_files(o);
    for (std::filesystem::path& f : study_figure_files(scene, o)) files.push_back(std::move(f));
    return files;
}

void run_study(const Scene& scene, const StudyOptions& options, Progress& progress) {
    StudyRunner(scene, options, progress).run();
}

}  // namespace hmcr
