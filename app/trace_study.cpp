// `hmcr trace-study SCENE --reference DIR --samplers all --spp 60 --seeds k -o OUT`: every pixel
// sampling criterion at one mean spp against a reference (studies/sampling_study.h).
#include <fmt/core.h>

#include <memory>
#include <sstream>

#include "app/command.h"
#include "app/terminal_progress.h"
#include "app/trace_flags.h"
#include "studies/sampling_study.h"

namespace hmcr {
namespace {

struct TraceStudyArgs {
    std::string scene;
    std::string samplers = "all";
    SamplingStudyOptions options = [] {
        SamplingStudyOptions o;
        o.trace.spp = 60;
        return o;
    }();
    TraceFlags flags;
    bool quiet = false;
};

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

int run_trace_study(TraceStudyArgs& a) {
    apply_trace_flags(a.flags, a.options.trace);
    a.options.samplers = split_commas(a.samplers);
    const Scene scene = load_scene(a.scene);
    TerminalProgress progress(progress_mode_for("auto", a.quiet), "hmcr trace-study");
    run_sampling_study(scene, a.options, progress);
    if (!a.quiet) fmt::print("study written to {}\n", a.options.output.string());
    return 0;
}

}  // namespace

Command trace_study_command(CLI::App& app) {
    auto a = std::make_shared<TraceStudyArgs>();
    auto* cmd = app.add_subcommand(
        "trace-study", "every pixel sampling criterion at one mean spp against a reference");
    SamplingStudyOptions& o = a->options;
    cmd->add_option("scene", a->scene, "bundled scene name, scene .json, or .obj")->required();
    cmd->add_option("--reference", o.reference, "folder of `hmcr trace-reference` (or reference)")
        ->required();
    cmd->add_option("--samplers", a->samplers, "comma-separated names, or all")
        ->capture_default_str();
    cmd->add_option("--spp", o.trace.spp, "mean samples per pixel of every image")
        ->capture_default_str();
    cmd->add_option("--seeds", o.seeds, "seeds per sampler")->capture_default_str();
    cmd->add_option("--first-seed", o.trace.seed, "the first seed")->capture_default_str();
    add_trace_flags(*cmd, o.trace, a->flags, {"sampler", "spp", "seed", "threshold", "width"});
    cmd->add_option("-o,--output", o.output, "output folder (rerunning resumes)")->required();
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a] { return run_trace_study(*a); }};
}

}  // namespace hmcr
