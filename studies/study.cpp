#include "studies/study.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <stdexcept>

#include "meshes/scene.h"
#include "oracles/registry.h"
#include "radiosity/patch.h"
#include "common/stopwatch.h"
#include "common/json_file.h"
#include "studies/reference.h"
#include "common/atomic_file.h"
#include "viz/image.h"
#include "viz/renderer.h"
#include "viz/shaded_tracer.h"
#include "viz/vtk_export.h"
#include "viz/vtk_import.h"

namespace hmcr {
namespace {

using Clock = std::chrono::steady_clock;

StudyProgress event(StudyProgress::Stage stage, std::size_t cell_index) {
    StudyProgress p;
    p.stage = stage;
    p.cell_index = cell_index;
    return p;
}

// What every cell is measured against, loaded once.
struct StudyReference {
    ShadedMesh mesh;
    std::map<std::string, Image8> images;  // quantised with the view's exposure
    std::map<std::string, double> exposure;
};

StudyReference load_reference(const std::filesystem::path& dir, const Scene& scene) {
    StudyReference ref;
    ref.mesh = read_vtp(dir / "reference.vtp");
    ref.exposure = read_reference_exposures(dir);
    for (const View& v : scene.views) {
        if (!ref.exposure.count(v.name)) {
            throw std::invalid_argument(fmt::format("{}: no exposure for view '{}' of scene '{}'",
                                                    (dir / "reference.json").string(), v.name,
                                                    scene.name));
        }
        const double exposure = ref.exposure.at(v.name);
        ref.images[v.name] = quantise(read_pfm(dir / "views" / (v.name + ".pfm")), exposure);
    }
    return ref;
}

std::vector<std::string> expand_oracles(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const std::string& n : names) {
        if (n == "all") {
            for (const Oracle* o : all_oracles()) out.emplace_back(o->name());
        } else {
            out.emplace_back(find_oracle(n).name());  // throws naming the valid ones
        }
    }
    return out;
}

void validate(const StudyOptions& o, const std::vector<std::string>& oracles) {
    if (o.budgets.empty()) throw std::invalid_argument("study: no budget given");
    if (oracles.empty()) throw std::invalid_argument("study: no oracle given");
    if (o.seeds < 1) throw std::invalid_argument("study: seeds must be at least 1");
    if (o.output.empty()) throw std::invalid_argument("study: no output folder given");
}

// One cell to run, and where its result lives.
struct CellTask {
    std::string oracle;
    std::size_t budget = 0;
    std::uint64_t seed = 0;
    std::string name;
};

class StudyRunner {
public:
    StudyRunner(const StudyOptions& o, const StudyProgressFn& progress)
        : m_options(o),
          m_progress(progress),
          m_scene(load_scene(o.scene)),
          m_oracles(expand_oracles(o.oracles)) {
        validate(o, m_oracles);
        for (std::size_t b : o.budgets)
            for (const std::string& oracle : m_oracles)
                for (int s = 0; s < o.seeds; ++s) {
                    const std::uint64_t seed = o.first_seed + std::uint64_t(s);
                    m_tasks.push_back({oracle, b, seed, cell_name(m_scene.name, oracle, b, seed)});
                }
        m_error_options = reflected_error_options(m_scene.mesh);
    }

    void run();

private:
    std::filesystem::path cell_file(const CellTask& t) const {
        return m_options.output / "cells" / (t.name + ".json");
    }
    CellResult compute(std::size_t index);
    void measure(const CellTask& t, const Solution& solution, CellResult& cell);
    void report(StudyProgress p) const;

    const StudyOptions& m_options;
    const StudyProgressFn& m_progress;
    Scene m_scene;
    std::vector<std::string> m_oracles;
    std::vector<CellTask> m_tasks;
    ObjectErrorOptions m_error_options;
    StudyReference m_reference;
    Clock::time_point m_start = Clock::now();
    std::size_t m_to_compute = 0, m_computed = 0;
    double m_compute_seconds = 0;
};

void StudyRunner::report(StudyProgress p) const {
    if (!m_progress) return;
    p.cell_count = m_tasks.size();
    p.cell = m_tasks[p.cell_index].name;
    p.elapsed_seconds = seconds_since(m_start);
    if (m_computed > 0) {
        const double per_cell = m_compute_seconds / double(m_computed);
        p.remaining_seconds = per_cell * double(m_to_compute - m_computed);
    }
    m_progress(p);
}

void StudyRunner::run() {
    m_reference = load_reference(m_options.reference, m_scene);
    for (const CellTask& t : m_tasks) m_to_compute += std::filesystem::exists(cell_file(t)) ? 0 : 1;
    std::vector<CellResult> cells;
    for (std::size_t i = 0; i < m_tasks.size(); ++i) {
        const std::filesystem::path file = cell_file(m_tasks[i]);
        if (std::filesystem::exists(file)) {
            cells.push_back(read_json_file(file, [](const nlohmann::json& j) {
                return cell_from_json(j);
            }));
            report(event(StudyProgress::Stage::kSkipped, i));
            continue;
        }
        const auto start = Clock::now();
        CellResult cell = compute(i);
        const nlohmann::json j = cell_to_json(cell);
        write_text_atomically(file, j.dump(2) + "\n");
        cells.push_back(cell_from_json(j));  // exactly what a resumed run reads back
        m_compute_seconds += seconds_since(start);
        ++m_computed;
        report(event(cell.ok() ? StudyProgress::Stage::kDone : StudyProgress::Stage::kFailed, i));
    }
    std::vector<std::string> views;
    for (const View& v : m_scene.views) views.push_back(v.name);
    write_study_tables(m_options, views, cells);
}

CellResult StudyRunner::compute(std::size_t index) {
    const CellTask& t = m_tasks[index];
    CellResult cell;
    cell.scene = m_scene.name;
    cell.oracle = t.oracle;
    cell.budget = t.budget;
    cell.seed = t.seed;
    SolverOptions so;
    so.oracle = t.oracle;
    so.lines = m_options.lines;
    so.rays = m_options.rays;
    so.seed = t.seed;
    so.threads = m_options.threads;
    const ProbeFn on_probe = [&](const BudgetProbe& p, int probe) {
        StudyProgress sp = event(StudyProgress::Stage::kProbe, index);
        sp.probe = probe;
        sp.last_probe = p;
        report(sp);
    };
    const auto start = Clock::now();
    try {
        const BudgetResult r =
            solve_for_budget(m_scene.mesh, so, {t.budget, m_options.budget_tolerance}, on_probe);
        cell.seconds = seconds_since(start);
        cell.probes = r.probes;
        cell.epsilon = r.solution.stats.epsilon;
        cell.leaves = r.solution.stats.leaves;
        report(event(StudyProgress::Stage::kMeasuring, index));
        measure(t, r.solution, cell);
    } catch (const std::invalid_argument& e) {
        cell.seconds = seconds_since(start);
        cell.status = "failed";
        cell.message = e.what();
    }
    return cell;
}

// The mesh file, the images and the metrics of a solved cell.
void StudyRunner::measure(const CellTask& t, const Solution& solution, CellResult& cell) {
    const ShadedMesh mesh =
        build_shaded_mesh(*solution.hierarchy, m_scene.mesh, m_options.crease_degrees);
    write_vtp(m_options.output / "meshes" / (t.name + ".vtp"), mesh,
              vtp_metadata(solution, double(t.budget)));
    const ShadedTracer tracer(mesh);
    const RenderOptions render_options{m_options.samples_per_axis};
    for (const View& v : m_scene.views) {
        const Image8 image =
            quantise(render(tracer, v, render_options), m_reference.exposure.at(v.name));
        write_png(m_options.output / "images" / (t.name + "-" + v.name + ".png"), image);
        cell.views[v.name] = image_errors(image, m_reference.images.at(v.name));
    }
    cell.object_error = object_space_error(tracer, mesh, m_reference.mesh, m_error_options);
}

}  // namespace

std::string cell_name(const std::string& scene, const std::string& oracle, std::size_t budget,
                      std::uint64_t seed) {
    return fmt::format("{}-{}-B{}-s{}", scene, oracle, budget, seed);
}

void run_study(const StudyOptions& options, const StudyProgressFn& progress) {
    StudyRunner(options, progress).run();
}

}  // namespace hmcr
