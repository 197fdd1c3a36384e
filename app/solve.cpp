// SPDX-License-Identifier: Apache-2.0
// `hmcr solve SCENE`: solve at epsilon or to a leaf budget, write SCENE.vtp and its summary.
#include <fmt/core.h>
#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "app/command.h"
#include "app/count.h"
#include "app/run_summary.h"
#include "app/scene_input.h"
#include "app/solver_flags.h"
#include "app/terminal_progress.h"
#include "common/atomic_file.h"
#include "common/file_names.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "common/stopwatch.h"
#include "meshes/patch_mesh.h"
#include "radiosity/budget_search.h"
#include "radiosity/hierarchy.h"
#include "radiosity/solver.h"
#include "viz/paraview_state.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

struct SolveArgs {
    std::string scene;
    std::string output;
    SolverOptions options;
    SolverFlags flags;
    BudgetOptions budget;  // leaves == 0: no budget, solve at epsilon
    double crease_degrees = kCreaseDegrees;
    std::string progress = "auto";
    bool quiet = false;
    SceneFlags scene_flags;
};

fs::path output_path(const SolveArgs& args, const Scene& scene) {
    fs::path vtp =
        args.output.empty() ? named_file("out", scene.name, ".vtp") : fs::path(args.output);
    if (vtp.extension() != ".vtp") {
        throw InputError("output must be a .vtp file, got " + quote(vtp.string()));
    }
    return vtp;
}

void report(const Scene& scene, const Solution& sol, const RunTimings& timings, const fs::path& vtp,
            const fs::path& json, const fs::path& pvsm) {
    if (sol.stats.back_face_fraction() > 0.01) {
        fmt::print(stderr,
                   "hmcr: warning: {:.1f}% of the shot power hit back faces "
                   "(flipped normals?)\n",
                   100 * sol.stats.back_face_fraction());
    }
    const std::string refining =
        sol.stats.refining_rays > 0 && sol.stats.refining_rays < sol.stats.rays
            ? fmt::format(" ({} refining the mesh, the rest frozen)", sol.stats.refining_rays)
            : "";
    fmt::print("{}: {} leaves, {} rays{} in {} iterations, {:.2f} s -> {}, {} and {}\n", scene.name,
               sol.stats.leaves, sol.stats.rays, refining, sol.stats.iterations.size(),
               timings.total_seconds, vtp.string(), json.string(), pvsm.string());
}

// One solve at epsilon when budget.leaves is 0, else a budget search. A solve at epsilon needs
// the mesh only for its patches (build_patch_set), which keep what the output needs of it, so
// the mesh is released before the rays are shot; a budget search keeps it, since every probe
// builds its patches from it.
BudgetResult solve_as_asked(PatchMesh& mesh, const SolverOptions& options,
                            const BudgetOptions& budget, const SolveInputs& inputs,
                            Progress& progress, const Ranks& ranks) {
    if (budget.leaves > 0) return solve_for_budget(mesh, options, budget, inputs, progress, ranks);
    check_root_count(mesh.n_faces(), element_limit(options));  // a root per face, at least
    const auto start = std::chrono::steady_clock::now();
    PatchSet patches = build_patch_set(mesh);
    release(mesh);
    const double patch_seconds = seconds_since(start);
    progress.stage("shooting rays");
    BudgetResult out;
    out.solution = solve(std::move(patches), options, inputs, progress, ranks);
    out.solution.stats.setup_seconds += patch_seconds;  // the patches are part of the setup
    return out;
}

// The budget options are checked whether or not a budget is given: a bad value is a mistake
// either way.
void check_budget(const SolveArgs& args, const CLI::App& cmd) {
    if (cmd.count("--budget") && args.budget.leaves == 0) {
        throw InputError("budget must be a positive leaf count, got 0");
    }
    validate(args.budget);
}

int run_solve(SolveArgs& args, const std::string& command_line) {
    const auto start = std::chrono::steady_clock::now();
    check_budget(args, *args.flags.command);
    if (!(args.crease_degrees >= 0 && args.crease_degrees <= 180)) {
        throw InputError(
            fmt::format("crease-angle must be in [0, 180] degrees, got {}", args.crease_degrees));
    }
    const ProgressMode mode = progress_mode_for(args.progress, args.quiet);
    Scene scene = load_scene_reporting(args.scene, args.quiet, SceneUse::solve, args.scene_flags);
    warn_specular(scene, args.quiet, SpecularUse::solve);
    apply_scene_settings(args.flags, scene, args.options);
    const fs::path vtp = output_path(args, scene);
    fs::path json = vtp, pvsm = vtp;
    json.replace_extension(".json");
    pvsm.replace_extension(".pvsm");  // ParaView's view of the .vtp (viz/paraview_state.h)
    refuse_overwriting({vtp, json, pvsm}, scene.inputs);
    refuse_replacing_scene_files({json});
    // Rank 0 writes: it alone checks, locks and holds the set; every rank learns of a refusal.
    std::optional<OutputSet> out;
    together(Ranks::world(), [&] {
        if (Ranks::world().root()) out.emplace(std::vector<fs::path>{vtp, json, pvsm});
    });
    const SceneIdentity identity = scene_identity(scene);  // before the solve releases the mesh
    RunTimings timings;
    timings.load_seconds = seconds_since(start);

    TerminalProgress progress(mode, "hmcr " + scene.name);
    BudgetResult found = solve_as_asked(scene.mesh, args.options, args.budget, {scene.views},
                                        progress, Ranks::world());
    Solution& sol = found.solution;
    if (!Ranks::world().root()) return 0;  // every rank holds the solution; rank 0 writes it

    const auto t_out = std::chrono::steady_clock::now();
    // Nothing needs the tree after the output: the shading releases it as early as it can.
    const std::vector<std::int32_t> cluster_ids = sol.cluster_of_side();
    sol.clusters.reset();  // it points into the tree
    ShadedMesh shaded = build_shaded_mesh(std::move(sol.hierarchy), args.crease_degrees);
    set_cluster_ids(shaded, cluster_ids);
    write_solution(out->temp(vtp), shaded, sol, identity, double(sol.stats.iterations.size()));
    write_paraview_state(out->temp(pvsm), vtp, find_view(scene, ""),
                         sol.stats.two_sided_patches > 0);
    timings.output_seconds = seconds_since(t_out);
    timings.total_seconds = seconds_since(start);
    auto summary = run_summary(scene, sol, timings, command_line, vtp.string());
    if (args.budget.leaves > 0) summary["budget"] = budget_json(args.budget, found.probes);
    write_text_atomically(out->temp(json), summary.dump(2) + "\n");
    out->commit();
    if (!args.quiet) report(scene, sol, timings, vtp, json, pvsm);
    return 0;
}

}  // namespace

Command solve_command(CLI::App& app, const std::string& command_line) {
    auto args = std::make_shared<SolveArgs>();
    auto* cmd = app.add_subcommand(
        "solve", "solve a scene and write its Gouraud mesh (.vtp + .json + .pvsm)");
    cmd->add_option("scene", args->scene,
                    "bundled scene name, scene .json, or mesh (.obj .mgf .ply .gltf .glb)")
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "output .vtp (default out/SCENE.vtp); the summary (.json) and a ParaView state "
                    "(.pvsm) go beside it");
    args->flags = add_solver_flags(*cmd, args->options);
    add_scene_flags(*cmd, args->scene_flags);
    cmd->add_option(
           "--budget", args->budget.leaves,
           "target leaf count: epsilon is searched for on a log scale (each probe a full solve)")
        ->transform(count_notation());
    cmd->add_option("--budget-tolerance", args->budget.tolerance,
                    "accepted relative distance to the budget")
        ->capture_default_str();
    cmd->add_option(
           "--crease-angle", args->crease_degrees,
           "patches meeting at a smaller angle are blended in the Gouraud values (degrees)")
        ->capture_default_str();
    cmd->add_option("--progress", args->progress, "auto, bar, lines or none")
        ->capture_default_str();
    cmd->add_flag("-q,--quiet", args->quiet, "print only errors");
    return {cmd, [args, command_line] { return run_solve(*args, command_line); }, true};
}

}  // namespace hmcr
