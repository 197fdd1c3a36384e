// The command line (SPEC sections 1-5): `hmcr solve`, `hmcr oracles`, `hmcr scenes`.
// Every user error is one line on stderr and exit code 2; nothing is written then.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "meshes/scene.h"
#include "oracles/registry.h"
#include "radiosity/budget_search.h"
#include "app/commands.h"
#include "app/terminal_progress.h"
#include "app/run_summary.h"
#include "radiosity/solver.h"
#include "common/stopwatch.h"
#include "common/atomic_file.h"
#include "viz/shaded_mesh.h"
#include "viz/vtk_export.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// What `hmcr solve` was told, before the scene's own defaults are known.
struct SolveArgs {
    std::string scene;
    std::string output;
    SolverOptions options;
    BudgetOptions budget;       // leaves == 0: no budget, solve at epsilon
    double crease_degrees = 30;
    std::string progress = "auto";
    bool quiet = false;
    CLI::App* app = nullptr;  // to ask which options were given
};

// Scene-file defaults ("solver" object) apply unless the option was given on the command line.
void apply_scene_defaults(const Scene& scene, SolveArgs& args) {
    const auto& d = scene.solver_defaults;  // its keys were checked by the scene loader
    auto take = [&](const char* key, const char* flag, auto& field) {
        if (!d.contains(key) || args.app->count(flag) != 0) return;
        try {
            field = d.at(key).get<std::remove_reference_t<decltype(field)>>();
        } catch (const nlohmann::json::exception& e) {
            throw SceneError(scene.source.string() + ": solver setting '" + key + "': " +
                             e.what());
        }
    };
    take("oracle", "--oracle", args.options.oracle);
    take("epsilon", "--epsilon", args.options.epsilon);
    take("lines", "--lines", args.options.lines);
    take("rays", "--rays", args.options.rays);
    take("seed", "--seed", args.options.seed);
    take("min_area", "--min-area", args.options.min_area);
    take("max_depth", "--max-depth", args.options.max_depth);
    take("stop", "--stop", args.options.stop);
}

void write_outputs(const fs::path& vtp, const Scene& scene, const Solution& sol, double crease) {
    const ShadedMesh mesh = build_shaded_mesh(*sol.hierarchy, scene.mesh, crease);
    write_vtp(vtp, mesh, vtp_metadata(sol, double(sol.stats.iterations.size())));
}

// One solve at epsilon, or the probes of a budget search (each a full solve), with progress.
BudgetResult solve_scene(const Scene& scene, const SolveArgs& args, ProgressMode mode) {
    ProgressReporter reporter(mode, "hmcr " + scene.name);
    auto progress = [&](double f) { reporter.update(f); };
    BudgetResult out;
    if (args.budget.leaves == 0) {
        out.solution = solve(scene.mesh, args.options, progress);
        reporter.finish();
        return out;
    }
    auto on_probe = [&](const BudgetProbe& p, int k) {
        reporter.finish();
        if (mode != ProgressMode::none) {
            fmt::print(stderr, "hmcr {}: budget probe {}: epsilon {:.4g} -> {} leaves ({:.1f} s)\n",
                       scene.name, k, p.epsilon, p.leaves, p.seconds);
        }
        reporter.restart();
    };
    // Without a terminal, one line per probe says enough; a bar per probe is fine.
    const ProgressFn probe_progress = mode == ProgressMode::bar ? ProgressFn(progress) : nullptr;
    return solve_for_budget(scene.mesh, args.options, args.budget, on_probe, probe_progress);
}

nlohmann::json budget_json(const BudgetOptions& budget, const std::vector<BudgetProbe>& probes) {
    return {{"target_leaves", budget.leaves},
            {"tolerance", budget.tolerance},
            {"probes", nlohmann::json(probes)}};
}

int run_solve(SolveArgs& args, const std::string& command_line) {
    const auto start = Clock::now();
    validate(args.options);  // fail on a bad option before loading anything
    if (!(args.crease_degrees >= 0 && args.crease_degrees <= 180)) {
        throw std::invalid_argument(fmt::format("crease-angle must be in [0, 180] degrees, got {}",
                                                args.crease_degrees));
    }
    const ProgressMode mode = progress_mode_for(args.progress, args.quiet);
    Scene scene = load_scene(args.scene);
    apply_scene_defaults(scene, args);
    const fs::path vtp = args.output.empty() ? fs::path("out") / (scene.name + ".vtp")
                                             : fs::path(args.output);
    if (vtp.extension() != ".vtp") {
        throw std::invalid_argument("output must be a .vtp file, got '" + vtp.string() + "'");
    }
    RunTimings timings;
    timings.load_seconds = seconds_since(start);

    BudgetResult found = solve_scene(scene, args, mode);
    const Solution& sol = found.solution;

    const auto t_out = Clock::now();
    write_outputs(vtp, scene, sol, args.crease_degrees);
    timings.output_seconds = seconds_since(t_out);
    timings.total_seconds = seconds_since(start);
    fs::path json = vtp;
    json.replace_extension(".json");
    auto summary = run_summary(scene, sol, timings, command_line, vtp.string());
    if (args.budget.leaves > 0) summary["budget"] = budget_json(args.budget, found.probes);
    write_text_atomically(json, summary.dump(2) + "\n");

    if (!args.quiet) {
        if (sol.stats.back_face_fraction() > 0.01) {
            fmt::print(stderr, "hmcr: warning: {:.1f}% of the shot power hit back faces "
                               "(flipped normals?)\n", 100 * sol.stats.back_face_fraction());
        }
        fmt::print("{}: {} leaves, {} rays in {} iterations, {:.2f} s -> {} and {}\n", scene.name,
                   sol.stats.leaves, sol.stats.rays, sol.stats.iterations.size(),
                   timings.total_seconds, vtp.string(), json.string());
    }
    return 0;
}

void add_solve(CLI::App& app, SolveArgs& args) {
    auto* cmd = app.add_subcommand("solve", "solve a scene and write its Gouraud mesh (.vtp + .json)");
    args.app = cmd;
    SolverOptions& o = args.options;
    cmd->add_option("scene", args.scene, "bundled scene name, scene .json, or .obj file")->required();
    cmd->add_option("-o,--output", args.output, "output .vtp (default out/SCENE.vtp); the summary "
                                                "goes beside it as .json");
    cmd->add_option("--oracle", o.oracle, "refinement oracle (see `hmcr oracles`)")
        ->capture_default_str();
    cmd->add_option("--epsilon", o.epsilon, "refinement threshold (default: the oracle's)");
    cmd->add_option("--lines", o.lines, "kernel lines per link, N_s")->capture_default_str();
    cmd->add_option("--rays", o.rays, "shooting rays over the whole solve")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--seed", o.seed, "random seed")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--threads", o.threads, "worker threads, 0 = all cores")->capture_default_str();
    cmd->add_option("--min-area", o.min_area, "smallest element area, relative to the total area")
        ->capture_default_str();
    cmd->add_option("--max-depth", o.max_depth, "quadtree depth limit (<= 24)")->capture_default_str();
    cmd->add_option("--stop", o.stop, "stop when unshot power < stop * emitted power")
        ->capture_default_str();
    cmd->add_option("--budget", args.budget.leaves,
                    "target leaf count: epsilon is found by bisection (each probe a full solve)")
        ->transform(count_notation());
    cmd->add_option("--budget-tolerance", args.budget.tolerance,
                    "accepted relative distance to the budget")
        ->capture_default_str();
    cmd->add_option("--cache-mb", o.cache_mb, "link cache size for line-based oracles, MiB")
        ->capture_default_str();
    cmd->add_option("--crease-angle", args.crease_degrees,
                    "patches meeting at a smaller angle are blended in the Gouraud values (degrees)")
        ->capture_default_str();
    cmd->add_option("--progress", args.progress, "auto, bar, lines or none")->capture_default_str();
    cmd->add_flag("-q,--quiet", args.quiet, "print only errors");
}

int list_oracles() {
    for (const Oracle* o : all_oracles()) {
        fmt::print("{:<8} {} (default epsilon {:g})\n", o->name(), o->description(),
                   o->default_epsilon());
    }
    return 0;
}

int list_scenes() {
    for (const auto& name : bundled_scene_names()) fmt::print("{}\n", name);
    return 0;
}

std::string join_args(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
    return s;
}

int fail(const std::string& message) {
    fmt::print(stderr, "hmcr: error: {}\n", message);
    return 2;
}

}  // namespace

int run_cli(int argc, char** argv) {
    CLI::App app{"hmcr: hierarchical Monte Carlo radiosity with information-theoretic refinement"};
    app.set_version_flag("--version", std::string("hmcr ") + HMCR_VERSION);
    app.require_subcommand(1);
    SolveArgs solve_args;
    add_solve(app, solve_args);
    RenderArgs render_args;
    ReferenceArgs reference_args;
    auto* render_cmd = add_render_command(app, render_args);
    auto* reference_cmd = add_reference_command(app, reference_args);
    StudyArgs study_args;
    auto* study_cmd = add_study_command(app, study_args);
    InfoArgs info_args;
    auto* info_cmd = add_info_command(app, info_args);
    auto* oracles = app.add_subcommand("oracles", "list the refinement oracles");
    auto* scenes = app.add_subcommand("scenes", "list the bundled scenes");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(std::string(e.what()) + " (see hmcr --help)");
    }
    try {
        if (oracles->parsed()) return list_oracles();
        if (scenes->parsed()) return list_scenes();
        if (render_cmd->parsed()) return run_render(render_args);
        if (reference_cmd->parsed()) return run_reference(reference_args, join_args(argc, argv));
        if (study_cmd->parsed()) return run_study_command(study_args);
        if (info_cmd->parsed()) return run_info(info_args);
        return run_solve(solve_args, join_args(argc, argv));
    } catch (const SceneError& e) {
        return fail(e.what());
    } catch (const std::invalid_argument& e) {
        return fail(e.what());
    } catch (const std::exception& e) {
        fmt::print(stderr, "hmcr: error: {}\n", e.what());
        return 1;
    }
}

}  // namespace hmcr
