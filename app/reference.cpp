// `hmcr reference SCENE -o DIR`: a converged reference (studies/reference.h).
#include "studies/reference.h"

#include <fmt/core.h>

#include <memory>
#include <optional>

#include "app/command.h"
#include "app/run_summary.h"
#include "app/scene_input.h"
#include "app/solver_flags.h"
#include "app/terminal_progress.h"
#include "common/output_paths.h"
#include "common/output_set.h"

namespace hmcr {
namespace {

struct ReferenceArgs {
    std::string scene;
    std::string output;
    ReferenceOptions options;
    SolverFlags flags;
    bool quiet = false;
    SceneFlags scene_flags;
};

int run_reference(ReferenceArgs& a, const std::string& command_line) {
    if (!(a.options.max_area > 0)) throw InputError("max-area must be positive");
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    warn_specular(scene, a.quiet, SpecularUse::solve);
    apply_scene_settings(a.flags, scene, a.options.solver);
    const std::filesystem::path dir(a.output);
    refuse_overwriting(reference_files(dir, scene), scene.inputs);
    // Rank 0 writes: it alone checks, locks and holds the set; every rank learns of a refusal.
    std::optional<OutputSet> out;
    together(Ranks::world(), [&] {
        if (Ranks::world().root()) out.emplace(reference_files(dir, scene), dir);
    });
    TerminalProgress progress(progress_mode_for("auto", a.quiet), "hmcr reference " + scene.name);
    const Reference ref = compute_reference(scene, a.options, progress, Ranks::world());
    if (!Ranks::world().root()) return 0;  // every rank holds the reference; rank 0 writes it
    RunTimings timings;
    timings.total_seconds = ref.seconds;
    write_reference(
        *out, dir, scene, ref, a.options,
        run_summary(scene, ref.solution, timings, command_line, (dir / "reference.vtp").string()));
    out->commit();
    if (!a.quiet) {
        const Rgb& bias = ref.truncation.relative;
        fmt::print(
            "{}: reference of {} elements, 2 x {} rays, {:.1f} s; seeds differ by {:.4f} "
            "(object-space relative L2); stopping left out {:.2g}/{:.2g}/{:.2g} of the "
            "reflected light (R/G/B) -> {}\n",
            scene.name, ref.solution.stats.leaves, a.options.solver.rays, ref.seconds,
            ref.object_error.relative_l2, bias[0], bias[1], bias[2], dir.string());
    }
    return 0;
}

}  // namespace

Command reference_command(CLI::App& app, const std::string& command_line) {
    auto a = std::make_shared<ReferenceArgs>();
    auto* cmd = app.add_subcommand(
        "reference", "a converged reference: uniform mesh, many rays, two seeds compared");
    ReferenceOptions& o = a->options;
    cmd->add_option("scene", a->scene, "bundled scene name, scene .json, .obj or .mgf")->required();
    cmd->add_option("-o,--output", a->output, "output folder")->required();
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_option("--max-area", o.max_area, "largest element area, m^2")->capture_default_str();
    // The uniform mesh has no oracle and no limits; rays and seeds are the reference's own.
    a->flags = add_solver_flags(*cmd, o.solver,
                                {"oracle", "epsilon", "lines", "min_area", "max_depth", "cache_mb",
                                 "link_weight", "refine_share", "clustering"},
                                {"rays", "seed"});
    cmd->add_option("--samples", o.samples_per_axis, "n x n rays per pixel of the view images")
        ->capture_default_str();
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a, command_line] { return run_reference(*a, command_line); }, true};
}

}  // namespace hmcr
