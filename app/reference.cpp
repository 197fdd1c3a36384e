// SPDX-License-Identifier: Apache-2.0
// `hmcr reference SCENE -o DIR`: a converged reference, of one of two kinds (docs/studies.md):
// points traced independently of any mesh (studies/point_reference.h, the default), or a fixed
// uniform mesh solved with many rays (studies/reference.h, `--kind mesh`).
#include "studies/reference.h"

#include <fmt/core.h>

#include <memory>
#include <optional>

#include "app/command.h"
#include "app/count.h"
#include "app/run_summary.h"
#include "app/scene_input.h"
#include "app/solver_flags.h"
#include "app/terminal_progress.h"
#include "app/trace_flags.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "studies/point_reference.h"
#include "studies/reference_size.h"

namespace hmcr {
namespace {

struct ReferenceArgs {
    std::string scene;
    std::string output;
    std::string kind = "auto";
    std::string for_budget;  // a leaf count: size the reference for studies up to it
    ReferenceOptions options;
    PointReferenceOptions points;
    SolverFlags flags;
    TraceFlags trace_flags;
    bool quiet = false;
    SceneFlags scene_flags;
    std::vector<const CLI::Option*> mesh_only, points_only;  // for the refusal of a mix
    std::string mesh_because;  // the mesh flag that made an auto reference a mesh reference
};

// One kind per run: a flag of the other kind is refused, not ignored.
void refuse_other_kind(const ReferenceArgs& a, bool points) {
    for (const CLI::Option* option : points ? a.mesh_only : a.points_only) {
        if (option->count() == 0) continue;
        const std::string why =
            a.mesh_because.empty()
                ? ""
                : fmt::format(" ({} makes it one; --kind points asks for points)", a.mesh_because);
        throw InputError(fmt::format("{} is for a {} reference; this one is a {} reference{}",
                                     option->get_name(), points ? "mesh" : "point",
                                     points ? "point" : "mesh", why));
    }
}

// The sizes --for-budget gives where the command line gives none, said in one line.
void size_for_budget(ReferenceArgs& a, const Scene& scene, bool points) {
    if (a.for_budget.empty()) return;
    const auto budget = parse_count(a.for_budget);
    if (!budget || *budget == 0) {
        throw InputError("for-budget: " + quote(a.for_budget) + " is not a positive leaf count");
    }
    const ReferenceSize size = reference_size_for_budget(scene, *budget);
    const CLI::App& cmd = *a.flags.command;
    std::string chose;
    if (points && cmd.count("--points") == 0) {
        a.points.points = size.points;
        chose = fmt::format("--points {}", size.points);
    }
    if (!points && cmd.count("--max-area") == 0) {
        a.options.max_area = size.max_area;
        chose = fmt::format("--max-area {:.3g}", size.max_area);
    }
    if (!a.quiet && !chose.empty()) {
        fmt::print("{}: for studies up to {} leaves: {} ({})\n", scene.name, *budget, chose,
                   size.why);
    }
}

int run_points(ReferenceArgs& a, const Scene& scene, const std::string& command_line) {
    apply_trace_flags(a.trace_flags, a.points.views);
    a.points.path = a.points.views.path;
    a.points.seed = a.options.solver.seed;
    a.points.threads = a.options.solver.threads;
    Scene sized = scene;
    for (View& v : sized.views) v = sized_view(v, a.trace_flags);
    validate_point_reference(sized, a.points);
    const std::filesystem::path dir(a.output);
    refuse_overwriting(point_reference_files(dir, sized), sized.inputs);
    std::optional<OutputSet> out;
    together(Ranks::world(), [&] {
        if (Ranks::world().root()) out.emplace(point_reference_files(dir, sized), dir);
    });
    TerminalProgress progress(progress_mode_for("auto", a.quiet), "hmcr reference " + scene.name);
    const PointReference ref = compute_point_reference(sized, a.points, progress, Ranks::world());
    if (!Ranks::world().root()) return 0;
    write_point_reference(*out, dir, sized, ref, a.points, command_line);
    out->commit();
    if (!a.quiet) {
        const PointReferenceReport& r = ref.report;
        fmt::print(
            "{}: point reference of {} points ({:.3g} m^2 each), 2 x {} paths, {:.1f} s; noise "
            "{:.4f} (object-space relative L2); seeds agree to {:.2g} +- {:.2g} -> {}\n",
            scene.name, ref.points.points.size(), r.area_per_point, a.points.paths, ref.seconds,
            r.noise, r.seed_check, r.seed_check_se, dir.string());
        if (r.noise > kNoiseWarning)
            fmt::print(stderr,
                       "hmcr: warning: the points' noise {:.3f} is above {}: object errors near it "
                       "are measured through its removal alone, with standard errors as large; "
                       "--paths {} brings it to about {}\n",
                       r.noise, kNoiseWarning, paths_for_target_noise(r.noise, a.points.paths),
                       kTargetNoise);
    }
    return 0;
}

int run_mesh(ReferenceArgs& a, const Scene& scene, const std::string& command_line) {
    if (!(a.options.max_area > 0)) throw InputError("max-area must be positive");
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
            "{}: reference of {} leaves ({} elements with their parents), 2 x {} rays, {:.1f} "
            "s; seeds differ by {:.4f} (object-space relative L2); stopping left out "
            "{:.2g}/{:.2g}/{:.2g} of the reflected light (R/G/B)",
            scene.name, ref.solution.stats.leaves, ref.solution.stats.elements,
            a.options.solver.rays, ref.seconds, ref.object_error.relative_l2, bias[0], bias[1],
            bias[2]);
        if (ref.discretisation.samples > 0) {
            fmt::print("; against {} points the mesh is off by {:.4f} +- {:.4f}",
                       ref.discretisation.samples, ref.discretisation.relative_l2,
                       ref.discretisation.standard_error);
        }
        fmt::print(" -> {}\n", dir.string());
    }
    return 0;
}

// The first of `options` the command line gives, or "".
std::string first_given(const std::vector<const CLI::Option*>& options) {
    for (const CLI::Option* option : options)
        if (option->count() > 0) return option->get_name();
    return "";
}

int run_reference(ReferenceArgs& a, const std::string& command_line) {
    if (a.kind != "auto" && a.kind != "points" && a.kind != "mesh") {
        throw InputError("kind must be auto, points or mesh, got " + quote(a.kind));
    }
    // auto: a mesh reference when a mesh flag is given (--max-area, --rays, ...), else points.
    if (a.kind == "auto") {
        a.mesh_because = first_given(a.mesh_only);
        a.kind = a.mesh_because.empty() ? "points" : "mesh";
    }
    const bool points = a.kind == "points";
    refuse_other_kind(a, points);
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    // A flag such as --sequence may be meant for the solves a reference judges: said, since it
    // changes the kind of reference.
    if (!a.quiet && !a.mesh_because.empty()) {
        fmt::print(
            "{}: a mesh reference, since {} is given (--kind points for a point reference)\n",
            scene.name, a.mesh_because);
    }
    warn_specular(scene, a.quiet, SpecularUse::solve);
    apply_scene_settings(a.flags, scene, a.options.solver);
    size_for_budget(a, scene, points);
    return points ? run_points(a, scene, command_line) : run_mesh(a, scene, command_line);
}

}  // namespace

Command reference_command(CLI::App& app, const std::string& command_line) {
    auto a = std::make_shared<ReferenceArgs>();
    auto* cmd = app.add_subcommand(
        "reference",
        "a converged reference: points traced without a mesh (default), or a uniform mesh");
    ReferenceOptions& o = a->options;
    cmd->add_option("scene", a->scene,
                    "bundled scene name, scene .json, or mesh (.obj .mgf .ply .gltf .glb)")
        ->required();
    cmd->add_option("-o,--output", a->output, "output folder")->required();
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_option("--kind", a->kind,
                    "points (radiosity at stratified points, path-traced; no mesh), mesh (a "
                    "uniform mesh solved with many rays), or auto: mesh when a mesh flag is "
                    "given, else points")
        ->capture_default_str();
    cmd->add_option("--for-budget", a->for_budget,
                    "size the reference (--points or --max-area) for studies up to this many "
                    "leaves");
    // The uniform mesh has no oracle and no limits; rays and seeds are the reference's own.
    a->flags = add_solver_flags(*cmd, o.solver, kNotReferenceSettings, kReferenceOwnSettings);
    for (const char* name : {"--rays", "--stop", "--max-elements", "--control-variate",
                             "--sequence", "--bidirectional", "--basis"}) {
        if (auto* option = cmd->get_option_no_throw(name)) a->mesh_only.push_back(option);
    }
    a->mesh_only.push_back(
        cmd->add_option("--max-area", o.max_area, "mesh: largest element area, m^2")
            ->capture_default_str());
    a->mesh_only.push_back(cmd->add_option("--samples", o.samples_per_axis,
                                           "mesh: n x n rays per pixel of the view images")
                               ->capture_default_str());
    a->mesh_only.push_back(
        cmd->add_option_function<std::uint64_t>(
               "--check-points", [&o](const std::uint64_t& n) { o.check_points = n; },
               "mesh: points its discretisation is checked against (0: none; default: 4 a "
               "uniform element, at most 20000)")
            ->transform(count_notation()));
    PointReferenceOptions& p = a->points;
    a->points_only.push_back(
        cmd->add_option("--points", p.points,
                        "points: how many (strata of A_T / points m^2 on every side)")
            ->transform(count_notation())
            ->capture_default_str());
    a->points_only.push_back(
        cmd->add_option("--strata-seed", p.strata_seed,
                        "points: another independent jitter of the same strata (0: the usual)")
            ->transform(count_notation())
            ->capture_default_str());
    a->points_only.push_back(cmd->add_option("--paths", p.paths, "points: paths per point and seed")
                                 ->transform(count_notation())
                                 ->capture_default_str());
    a->points_only.push_back(
        cmd->add_option("--spp", p.views.spp, "points: samples per pixel of the traced views")
            ->capture_default_str());
    add_trace_flags(*cmd, p.views, a->trace_flags,
                    {"sampler", "spp", "threshold", "adaptive", "seed", "threads"});
    for (const char* name : {"--bounces", "--estimator", "--width"}) {
        a->points_only.push_back(cmd->get_option(name));
    }
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a, command_line] { return run_reference(*a, command_line); }, true};
}

}  // namespace hmcr
