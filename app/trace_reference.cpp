// SPDX-License-Identifier: Apache-2.0
// `hmcr trace-reference SCENE -o DIR`: every view path-traced with the uniform sampler at many
// samples per pixel (studies/traced_reference.h), the yardstick of a sampling study.
#include <fmt/core.h>

#include <memory>

#include "app/command.h"
#include "app/scene_input.h"
#include "app/terminal_progress.h"
#include "app/trace_flags.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "studies/traced_reference.h"

namespace hmcr {
namespace {

struct TraceReferenceArgs {
    std::string scene, output;
    TraceOptions options = [] {
        TraceOptions o;
        o.spp = 4096;
        return o;
    }();
    TraceFlags flags;
    bool quiet = false;
    SceneFlags scene_flags;
};

int run_trace_reference(TraceReferenceArgs& a, const std::string& command_line) {
    apply_trace_flags(a.flags, a.options);
    a.options.sampler = &uniform_criterion();
    validate_trace_options(a.options);
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    const std::filesystem::path dir(a.output);
    refuse_overwriting(traced_reference_files(dir, scene), scene.inputs);
    OutputSet out(traced_reference_files(dir, scene), dir);
    std::vector<View> views;
    for (const View& v : scene.views) views.push_back(sized_view(v, a.flags));
    TerminalProgress progress(progress_mode_for("auto", a.quiet),
                              "hmcr trace-reference " + scene.name);
    const TracedReference ref = compute_traced_reference(scene, views, a.options, progress);
    write_traced_reference(out, dir, scene, ref, a.options, command_line);
    out.commit();
    if (!a.quiet) {
        fmt::print("{}: {} views at {} samples per pixel, {:.1f} s -> {}\n", scene.name,
                   views.size(), a.options.spp, ref.seconds, a.output);
    }
    return 0;
}

}  // namespace

Command trace_reference_command(CLI::App& app, const std::string& command_line) {
    auto a = std::make_shared<TraceReferenceArgs>();
    auto* cmd = app.add_subcommand(
        "trace-reference", "path-trace every view uniformly at many samples: a study's reference");
    cmd->add_option("scene", a->scene,
                    "bundled scene name, scene .json, or mesh (.obj .mgf .ply .gltf .glb)")
        ->required();
    cmd->add_option("-o,--output", a->output, "output folder")->required();
    cmd->add_option("--spp", a->options.spp, "samples per pixel")->capture_default_str();
    add_trace_flags(*cmd, a->options, a->flags, {"sampler", "spp", "threshold", "adaptive"});
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a, command_line] { return run_trace_reference(*a, command_line); }};
}

}  // namespace hmcr
