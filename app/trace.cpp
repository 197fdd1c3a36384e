// SPDX-License-Identifier: Apache-2.0
// `hmcr trace SCENE -o IMAGE.png`: a path-traced image of one view (trace/trace_image.h), with
// its sampling density map (IMAGE-density.png) and a JSON summary (IMAGE.json) beside it.
#include <fmt/core.h>
#include <tbb/info.h>

#include <chrono>
#include <memory>

#include "app/command.h"
#include "app/exposure.h"
#include "app/run_summary.h"
#include "app/scene_input.h"
#include "app/terminal_progress.h"
#include "app/trace_flags.h"
#include "common/atomic_file.h"
#include "common/memory.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "common/stopwatch.h"
#include "image/density_map.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

struct TraceArgs {
    std::string scene, view, output, pfm;
    ExposureChoice exposure;
    TraceOptions options;
    TraceFlags flags;
    std::string progress = "auto";
    bool quiet = false;
    SceneFlags scene_flags;
};

// IMAGE.png -> IMAGE-density.png and IMAGE.json.
fs::path beside(const fs::path& png, const std::string& suffix, const std::string& extension) {
    return png.parent_path() / (png.stem().string() + suffix + extension);
}

nlohmann::json summary(const TraceArgs& a, const Scene& scene, const View& view,
                       const TraceResult& r, double exposure, const std::string& command_line) {
    const SampleCounts c = r.counts();
    nlohmann::json probes = nlohmann::json::array();
    for (const ThresholdProbe& p : r.probes)
        probes.push_back({{"threshold", p.threshold}, {"spp", p.spp}});
    const TraceOptions& o = a.options;
    return {{"hmcr_version", HMCR_VERSION},
            {"command", command_line},
            {"scene", scene.name},
            {"view", view.name},
            {"width", view.width},
            {"height", view.height},
            {"sampler", o.sampler->name()},
            {"spp",
             {{"target", o.spp},
              {"achieved", c.mean},
              {"min", c.min},
              {"max", c.max},
              {"tolerance", o.spp_tolerance},
              {"max_per_pixel", max_samples_per_pixel(o)}}},
            {"allocation", allocation_name(o.allocation)},
            {"fresh", o.fresh},
            {"threshold", r.threshold},  // NaN (uniform, map) is written as null
            {"threshold_probes", probes},
            {"seed", o.seed},
            {"path",
             {{"estimator", estimator_name(o.path.estimator)},
              {"max_depth", o.path.max_depth},
              {"roulette_depth", o.path.roulette_depth}}},
            {"tree_depth", o.tree_depth},
            {"threads", o.threads > 0 ? o.threads : tbb::info::default_concurrency()},
            {"rays", {{"image", r.rays}, {"traced", r.rays_traced}}},
            {"exposure", exposure},
            {"seconds", r.seconds},
            {"peak_memory_bytes", peak_memory_bytes()}};
}

// The files a trace writes: IMAGE.png, IMAGE-density.png, IMAGE.json and the optional .pfm.
std::vector<fs::path> outputs(const TraceArgs& a) {
    const fs::path png(a.output);
    std::vector<fs::path> out{png, beside(png, "-density", ".png"), beside(png, "", ".json")};
    if (!a.pfm.empty()) out.emplace_back(a.pfm);
    return out;
}

// Every option and output checked before any work: a bad run is refused with nothing written.
std::vector<fs::path> check_outputs(const TraceArgs& a, const Scene& scene) {
    if (fs::path(a.output).extension() != ".png") {
        throw InputError("output must be a .png file, got " + quote(a.output));
    }
    if (!a.pfm.empty() && fs::path(a.pfm).extension() != ".pfm") {
        throw InputError("pfm must be a .pfm file, got " + quote(a.pfm));
    }
    std::vector<fs::path> inputs = scene.inputs;
    for (const auto& in : exposure_inputs(a.exposure)) inputs.push_back(in);
    std::vector<fs::path> out = outputs(a);
    refuse_overwriting(out, inputs);
    refuse_replacing_scene_files(out);
    return out;
}

int run_trace(TraceArgs& a, const std::string& command_line) {
    apply_trace_flags(a.flags, a.options);
    validate_trace_options(a.options);
    check_exposure(a.exposure);
    const ProgressMode mode = progress_mode_for(a.progress, a.quiet);
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    OutputSet out(check_outputs(a, scene));
    const fs::path png(a.output), density = beside(png, "-density", ".png");
    const View view = sized_view(find_view(scene, a.view), a.flags);
    check_trace_memory(a.options, view);
    const double fixed = fixed_exposure(a.exposure, view.name);
    const PathTracer tracer(build_patch_set(scene.mesh), a.options.path);
    TerminalProgress progress(mode, "hmcr trace " + scene.name);
    const TraceResult r = trace_image(tracer, view, a.options, progress);
    const double exposure = image_exposure(fixed, r.image);
    write_png(out.temp(png), r.image, exposure);
    write_png(out.temp(density), density_map(r.samples, view.width, view.height));
    if (!a.pfm.empty()) write_pfm(out.temp(a.pfm), r.image);
    write_text_atomically(out.temp(beside(png, "", ".json")),
                          summary(a, scene, view, r, exposure, command_line).dump(2) + "\n");
    out.commit();
    warn_if_black(r.image, exposure, png.string(), a.scene, view.name, a.quiet);
    if (!a.quiet) {
        fmt::print("{} {}: {} at {:.2f} samples per pixel, {} rays, {:.1f} s -> {}\n", scene.name,
                   view.name, a.options.sampler->name(), r.counts().mean, r.rays_traced, r.seconds,
                   png.string());
    }
    return 0;
}

}  // namespace

Command trace_command(CLI::App& app, const std::string& command_line) {
    auto a = std::make_shared<TraceArgs>();
    auto* cmd = app.add_subcommand("trace", "path-trace a view, with adaptive supersampling");
    cmd->add_option("scene", a->scene,
                    "bundled scene name, scene .json, or mesh (.obj .mgf .ply .gltf .glb)")
        ->required();
    add_view_flag(*cmd, a->view);
    cmd->add_option("-o,--output", a->output,
                    "8-bit sRGB .png; IMAGE-density.png and IMAGE.json go beside it")
        ->required();
    cmd->add_option("--pfm", a->pfm, "also write the linear radiance as .pfm");
    add_trace_flags(*cmd, a->options, a->flags);
    add_exposure_flags(*cmd, a->exposure);
    cmd->add_option("--progress", a->progress, "auto, bar, lines or none")->capture_default_str();
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a, cmd, command_line] {
                note_exposure_given(*cmd, a->exposure);
                return run_trace(*a, command_line);
            }};
}

}  // namespace hmcr
