// `hmcr study SCENE --reference DIR --budgets N,N`: every oracle x budget x seed, tables, plots.
#include <fmt/core.h>

#include <memory>
#include <sstream>

#include "app/scene_input.h"
#include "app/command.h"
#include "app/count.h"
#include "app/solver_flags.h"
#include "app/terminal_progress.h"
#include "common/output_paths.h"
#include "studies/study.h"

namespace hmcr {
namespace {

struct StudyArgs {
    std::string scene;
    StudyOptions options;
    SolverFlags flags;
    std::string budgets;  // "2000,5000,19000"
    std::string oracles = "all";
    std::string mesh_rays;  // empty: the default, kMeshRaysPerCellRay x the cell's rays
    bool quiet = false;
};

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        if (item.empty()) throw InputError("empty item in the list " + quote(text));
        out.push_back(item);
    }
    return out;
}

std::size_t parse_budget(const std::string& text) {
    const auto count = parse_count(text);
    if (!count || *count == 0) {
        throw InputError("budgets: " + quote(text) + " is not a positive leaf count");
    }
    return std::size_t(*count);
}

int run_study(StudyArgs& a) {
    for (const auto& b : split_commas(a.budgets)) a.options.budgets.push_back(parse_budget(b));
    a.options.oracles = split_commas(a.oracles);
    if (!a.mesh_rays.empty()) {
        const auto rays = parse_count(a.mesh_rays);
        if (!rays || *rays > kMaxRays) {
            throw InputError("mesh-rays: " + quote(a.mesh_rays) + " is not a count up to 1e15");
        }
        a.options.mesh_rays = *rays;
    }
    validate_study(a.options);
    const Scene scene = load_scene_reporting(a.scene, a.quiet);
    apply_scene_settings(a.flags, scene, a.options.solver);
    const std::filesystem::path& out = a.options.output;
    refuse_nested_dirs(out, a.options.reference);
    refuse_overwriting({out / "table.json", out / "table.csv", out / "table.md"}, scene.inputs);
    prepare_output_dir(out);
    TerminalProgress progress(progress_mode_for("auto", a.quiet), "hmcr study");
    run_study(scene, a.options, progress);
    if (!a.quiet) fmt::print("study written to {}\n", a.options.output.string());
    return 0;
}

}  // namespace

Command study_command(CLI::App& app) {
    auto a = std::make_shared<StudyArgs>();
    auto* cmd = app.add_subcommand(
        "study", "every oracle x budget x seed against a reference: tables, images, plots");
    StudyOptions& o = a->options;
    cmd->add_option("scene", a->scene, "bundled scene name, scene .json, or .obj")->required();
    cmd->add_option("--reference", o.reference, "folder written by `hmcr reference`")->required();
    cmd->add_option("--budgets", a->budgets, "leaf counts, comma-separated")->required();
    cmd->add_option("--oracles", a->oracles, "comma-separated names, or all")->capture_default_str();
    cmd->add_option("--seeds", o.seeds, "seeds per cell")->capture_default_str();
    cmd->add_option("--first-seed", o.solver.seed, "the first seed")
        ->transform(count_notation())
        ->capture_default_str();
    // Every cell sets its oracle, epsilon (by the budget search) and seed.
    a->flags = add_solver_flags(*cmd, o.solver, {"oracle", "epsilon", "seed"});
    cmd->add_option("--rays-per-leaf", o.rays_per_leaf,
                    "give each budget this many rays per leaf instead of --rays (0: --rays)")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--mesh-rays", a->mesh_rays,
                    fmt::format("rays of each cell's frozen re-solve, the mesh error (default: "
                                "{} x the cell's rays; 0: none)",
                                kMeshRaysPerCellRay));
    cmd->add_option("--budget-tolerance", o.budget_tolerance, "relative")->capture_default_str();
    cmd->add_option("--samples", o.samples_per_axis, "n x n rays per pixel")->capture_default_str();
    cmd->add_option("-o,--output", o.output, "output folder (rerunning resumes)")->required();
    cmd->add_flag("--redo", o.redo_other_settings,
                  "compute again the cells of the output folder made with other settings");
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a] { return run_study(*a); }};
}

}  // namespace hmcr
