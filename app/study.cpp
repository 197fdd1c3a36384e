// SPDX-License-Identifier: Apache-2.0
// `hmcr study SCENE --reference DIR -o OUT` and one of
//   --budgets N,N [--oracles LIST]   a meshing study: every oracle x budget x seed
//   (studies/study.h)
//   --samplers LIST [--spp N,N]      a sampling study: every pixel sampler x seed at each mean spp
//                                    (studies/sampling_study.h)
// Either takes a radiosity reference (`hmcr reference`) or a traced one (`hmcr trace-reference`).
#include "studies/study.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>

#include "app/command.h"
#include "app/count.h"
#include "app/named_list.h"
#include "app/plot_script.h"
#include "app/scene_input.h"
#include "app/solver_flags.h"
#include "app/terminal_progress.h"
#include "app/trace_flags.h"
#include "common/output_paths.h"
#include "common/ranks.h"
#include "studies/sampling_study.h"
#include "trace/criteria/registry.h"

namespace hmcr {
namespace {

struct StudyArgs {
    std::string scene;
    StudyOptions options;
    SolverFlags flags;
    std::string budgets;  // "2000,5000,19000"
    std::string oracles = "all";
    std::string mesh_rays;    // empty: the default, kMeshRaysPerCellRay x the cell's rays
    std::string samplers;     // "all" or "uniform,srhe"; given: a sampling study
    std::string spps = "60";  // "16,32,60,128"
    std::string columns;      // "seeds,psnr_p"; empty: every column in table.md, a few in .tex
    SamplingStudyOptions sampling;
    TraceFlags trace_flags;
    std::vector<const CLI::Option*> meshing_only, sampling_only;  // for the refusal of a mix
    bool quiet = false;
    SceneFlags scene_flags;
};

// The items of a comma-separated list (no list: none); an empty item, at either end as between
// two commas ("20,", ",20", "20,,40"), is refused.
std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> out;
    if (text.empty()) return out;
    for (std::size_t start = 0;;) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma == start) throw InputError("empty item in the list " + quote(text));
        out.push_back(text.substr(start, comma - start));
        if (comma == text.size()) return out;
        start = comma + 1;
    }
}

double parse_spp(const std::string& text) {
    double spp = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, spp);
    if (error != std::errc() || stop != end || !std::isfinite(spp) || !(spp > 0)) {
        throw InputError("spp: " + quote(text) + " is not a positive number of samples per pixel");
    }
    return spp;
}

std::size_t parse_budget(const std::string& text) {
    const auto count = parse_count(text);
    if (!count || *count == 0) {
        throw InputError("budgets: " + quote(text) + " is not a positive leaf count");
    }
    return std::size_t(*count);
}

// One kind of study per run: a flag of the other kind is refused, not ignored.
void refuse_mixed_flags(const StudyArgs& a, bool sampling) {
    const auto& other = sampling ? a.meshing_only : a.sampling_only;
    for (const CLI::Option* option : other) {
        if (option->count() == 0) continue;
        throw InputError(fmt::format("{} is for a {} study; a {} study ({}) does not use it",
                                     option->get_name(), sampling ? "meshing" : "sampling",
                                     sampling ? "sampling" : "meshing",
                                     sampling ? "--samplers" : "--budgets"));
    }
}

// The checks of either kind before any work: the output folder is neither in nor around the
// reference, and no table replaces an input. The study itself then checks, makes and locks its
// folder, and checks every cell's files, before its first cell.
void refuse_study_output(const std::filesystem::path& out, const std::filesystem::path& reference,
                         const std::vector<std::filesystem::path>& files, const Scene& scene) {
    refuse_nested_dirs(out, reference);
    refuse_overwriting(files, scene.inputs);
}

// Rank 0 has written the tables and the plot data: it draws the plots.
void finish_study(const std::filesystem::path& out, bool quiet) {
    if (!Ranks::world().root()) return;
    draw_study_plots(out, quiet);
    if (!quiet) fmt::print("study written to {}\n", out.string());
}

int run_sampling_study_command(StudyArgs& a) {
    SamplingStudyOptions& o = a.sampling;
    o.reference = a.options.reference;
    o.output = a.options.output;
    o.seeds = a.options.seeds;
    o.trace.seed = a.options.solver.seed;
    o.trace.threads = a.options.solver.threads;
    o.redo_other_settings = a.options.redo_other_settings;
    o.columns = split_commas(a.columns);
    o.samplers = named_list(criterion_registry(), split_commas(a.samplers));
    o.spps.clear();
    for (const std::string& spp : split_commas(a.spps)) o.spps.push_back(parse_spp(spp));
    apply_trace_flags(a.trace_flags, o.trace);
    validate_sampling_study(o);
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    refuse_study_output(o.output, o.reference, sampling_study_output_files(scene, o), scene);
    TerminalProgress progress(progress_mode_for("auto", a.quiet), "hmcr study");
    run_sampling_study(scene, o, progress);
    finish_study(o.output, a.quiet);
    return 0;
}

int run_meshing_study(StudyArgs& a) {
    if (a.options.rays_per_leaf > 0 && a.flags.command->count("--rays") > 0) {
        throw InputError(
            "give --rays-per-leaf or --rays, not both: --rays-per-leaf sets every "
            "cell's rays (R x its budget)");
    }
    for (const auto& b : split_commas(a.budgets)) a.options.budgets.push_back(parse_budget(b));
    a.options.oracles = named_list(oracle_registry(), split_commas(a.oracles));
    a.options.columns = split_commas(a.columns);
    if (!a.mesh_rays.empty()) {
        const auto rays = parse_count(a.mesh_rays);
        if (!rays || *rays > kMaxRays) {
            throw InputError("mesh-rays: " + quote(a.mesh_rays) + " is not a count up to 1e15");
        }
        a.options.mesh_rays = *rays;
    }
    a.options.strict = a.scene_flags.strict;  // refuses cells finer than the reference too
    validate_study(a.options);
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    warn_specular(scene, a.quiet, SpecularUse::solve);
    apply_scene_settings(a.flags, scene, a.options.solver);
    refuse_study_output(a.options.output, a.options.reference, study_output_files(scene, a.options),
                        scene);
    TerminalProgress progress(progress_mode_for("auto", a.quiet), "hmcr study");
    run_study(scene, a.options, progress);
    finish_study(a.options.output, a.quiet);
    return 0;
}

int run_study_command(StudyArgs& a) {
    const bool sampling = !a.samplers.empty();
    if (sampling == !a.budgets.empty()) {
        throw InputError(
            "study: give --budgets (a meshing study) or --samplers (a sampling study)" +
            std::string(sampling ? ", not both" : ""));
    }
    refuse_mixed_flags(a, sampling);
    return sampling ? run_sampling_study_command(a) : run_meshing_study(a);
}

// The options `add` puts on `cmd`.
template <class Add>
std::vector<const CLI::Option*> options_added(CLI::App& cmd, Add&& add) {
    const auto before = cmd.get_options();
    add();
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* o : cmd.get_options()) {
        if (std::find(before.begin(), before.end(), o) == before.end()) out.push_back(o);
    }
    return out;
}

void add_meshing_flags(CLI::App& cmd, StudyArgs& a) {
    StudyOptions& o = a.options;
    cmd.add_option("--budgets", a.budgets, "meshing study: leaf counts, comma-separated");
    cmd.add_option("--oracles", a.oracles, "comma-separated names, or all")->capture_default_str();
    // Every cell sets its oracle, epsilon (by the budget search) and seed; threads is shared.
    a.flags = add_solver_flags(cmd, o.solver, {"oracle", "epsilon", "seed", "threads"});
    cmd.add_option("--rays-per-leaf", o.rays_per_leaf,
                   "give each budget this many rays per leaf instead of --rays (0: --rays)")
        ->transform(count_notation())
        ->capture_default_str();
    cmd.add_option("--mesh-rays", a.mesh_rays,
                   fmt::format("rays of each cell's frozen re-solve, the mesh error (default: "
                               "{} x the cell's rays; 0: none)",
                               kMeshRaysPerCellRay));
    cmd.add_option("--budget-tolerance", o.budget_tolerance,
                   "accepted relative distance of a cell's leaf count to its budget, in (0, 1)")
        ->capture_default_str();
    cmd.add_option("--samples", o.samples_per_axis, "n x n rays per pixel of the images")
        ->capture_default_str();
}

void add_sampling_flags(CLI::App& cmd, StudyArgs& a) {
    cmd.add_option("--samplers", a.samplers,
                   "sampling study: pixel samplers, comma-separated, or all");
    cmd.add_option("--spp", a.spps,
                   "mean samples per pixel of every image, or several, comma-separated: a cell "
                   "per spp value")
        ->capture_default_str();
    add_trace_flags(
        cmd, a.sampling.trace, a.trace_flags,
        {"sampler", "spp", "seed", "threshold", "width", "threads", "criterion-exposure"});
    cmd.add_flag("--display-criteria", a.sampling.display_criteria,
                 "adaptive samplers judge display values: radiance at the reference's exposure "
                 "of the view, clamped to [0, 1]");
}

}  // namespace

Command study_command(CLI::App& app) {
    auto a = std::make_shared<StudyArgs>();
    auto* cmd = app.add_subcommand(
        "study",
        "oracles at element budgets (--budgets) or pixel samplers at spp values (--samplers) "
        "against a reference: tables, images, plots");
    StudyOptions& o = a->options;
    cmd->add_option("scene", a->scene,
                    "bundled scene name, scene .json, or mesh (.obj .mgf .ply .gltf .glb)")
        ->required();
    cmd->add_option("--reference", o.reference,
                    "folder written by `hmcr reference` or `hmcr trace-reference`")
        ->required();
    a->meshing_only = options_added(*cmd, [&] { add_meshing_flags(*cmd, *a); });
    a->sampling_only = options_added(*cmd, [&] { add_sampling_flags(*cmd, *a); });
    cmd->add_option("--seeds", o.seeds, "seeds per cell")->capture_default_str();
    cmd->add_option("--first-seed", o.solver.seed, "the first seed")
        ->transform(count_notation())
        ->capture_default_str();
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_option("--threads", o.solver.threads,
                    "worker threads, 0 = all cores; results do "
                    "not depend on it")
        ->capture_default_str();
    cmd->add_option("-o,--output", o.output, "output folder (rerunning resumes)")->required();
    cmd->add_option("--columns", a->columns,
                    "columns of table.md and table.tex, comma-separated, or all (default: every "
                    "one in table.md, a few that fit a page in table.tex); tables only, no cell "
                    "setting");
    cmd->add_flag("--redo", o.redo_other_settings,
                  "compute again the cells of the output folder made with other settings");
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a] { return run_study_command(*a); }, true};
}

}  // namespace hmcr
