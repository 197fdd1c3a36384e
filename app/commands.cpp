#include "app/commands.h"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "app/run_summary.h"
#include "common/stopwatch.h"
#include "information/leaf_patches.h"
#include "information/scene_information.h"
#include "viz/vtk_import.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

const View& find_view(const Scene& scene, const std::string& name) {
    if (scene.views.empty()) throw std::invalid_argument(scene.name + " has no views");
    if (name.empty()) return scene.views.front();
    std::string names;
    for (const View& v : scene.views) {
        if (v.name == name) return v;
        names += (names.empty() ? "" : ", ") + v.name;
    }
    throw std::invalid_argument("scene " + scene.name + " has no view '" + name + "' (views: " +
                                names + ")");
}

// The exposure a reference folder fixed for a view.
double reference_exposure(const fs::path& dir, const std::string& view) {
    const auto exposure = read_reference_exposures(dir);
    if (!exposure.count(view)) {
        throw std::invalid_argument((dir / "reference.json").string() + ": no view '" + view + "'");
    }
    return exposure.at(view);
}

}  // namespace

std::optional<std::uint64_t> parse_count(const std::string& text) {
    std::size_t used = 0;
    double value = 0;
    // Plain digits are read exactly (up to 2^64 - 1); notation like 1e7 up to 2^53, where
    // doubles are exact.
    const bool plain = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    try {
        if (plain) return std::stoull(text);
        value = std::stod(text, &used);
    } catch (const std::exception&) {  // out of range, or not a number at all
        return std::nullopt;
    }
    if (used != text.size() || !(value >= 0) || value > 0x1p53 || value != std::floor(value)) {
        return std::nullopt;
    }
    return std::uint64_t(value);
}

const CLI::Validator& count_notation() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            const auto count = parse_count(text);
            if (!count) return "'" + text + "' is not a whole number in range";
            text = std::to_string(*count);
            return {};
        },
        "COUNT");
    return validator;
}

CLI::App* add_render_command(CLI::App& app, RenderArgs& a) {
    auto* cmd = app.add_subcommand("render", "render a solution (.vtp) from a view of its scene");
    cmd->add_option("solution", a.solution, "the solution's .vtp")->required();
    cmd->add_option("--scene", a.scene, "the scene it solves (for its views)")->required();
    cmd->add_option("--view", a.view, "view name (default: the scene's first)");
    cmd->add_option("-o,--output", a.output, "8-bit sRGB .png")->required();
    cmd->add_option("--pfm", a.pfm, "also write the linear radiance as .pfm");
    cmd->add_option("--samples", a.options.samples_per_axis, "n x n rays per pixel")
        ->capture_default_str();
    auto* exposure =
        cmd->add_option("--exposure", a.exposure, "fixed exposure (default: from this image)");
    cmd->add_option("--reference", a.reference, "use the exposure of this reference folder")
        ->excludes(exposure);
    return cmd;
}

int run_render(const RenderArgs& a) {
    if (a.options.samples_per_axis < 1 || a.options.samples_per_axis > 16) {
        throw std::invalid_argument("samples must be in 1..16");
    }
    const Scene scene = load_scene(a.scene);
    const View& view = find_view(scene, a.view);
    double exposure = a.exposure;
    if (!a.reference.empty()) exposure = reference_exposure(a.reference, view.name);
    const ShadedMesh mesh = read_vtp(a.solution);
    const Image image = render(mesh, view, a.options);
    if (exposure <= 0) exposure = exposure_from(image);
    write_png(a.output, image, exposure);
    if (!a.pfm.empty()) write_pfm(a.pfm, image);
    return 0;
}

CLI::App* add_reference_command(CLI::App& app, ReferenceArgs& a) {
    auto* cmd = app.add_subcommand(
        "reference", "a converged reference: uniform mesh, many rays, two seeds compared");
    ReferenceOptions& o = a.options;
    cmd->add_option("scene", a.scene, "bundled scene name, scene .json, or .obj")->required();
    cmd->add_option("-o,--output", a.output, "output folder")->required();
    cmd->add_option("--max-area", o.max_area, "largest element area, m^2")->capture_default_str();
    cmd->add_option("--rays", o.rays, "rays per seed")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--seed", o.seed, "first seed (the second is seed + 1)")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--samples", o.samples_per_axis, "n x n rays per pixel of the view images")
        ->capture_default_str();
    cmd->add_option("--threads", o.threads, "worker threads, 0 = all")->capture_default_str();
    cmd->add_flag("-q,--quiet", a.quiet, "print only errors");
    return cmd;
}

int run_reference(const ReferenceArgs& a, const std::string& command_line) {
    if (!(a.options.max_area > 0)) throw std::invalid_argument("max-area must be positive");
    if (a.options.rays < 1) throw std::invalid_argument("rays must be at least 1");
    const Scene scene = load_scene(a.scene);
    const auto progress = [&](const std::string& step) {
        if (!a.quiet) fmt::print(stderr, "hmcr reference {}: {}\n", scene.name, step);
    };
    const Reference ref = compute_reference(scene, a.options, progress);
    RunTimings timings;
    timings.total_seconds = ref.seconds;
    const fs::path dir(a.output);
    write_reference(dir, scene, ref, a.options,
                    run_summary(scene, ref.solution, timings, command_line,
                                (dir / "reference.vtp").string()));
    if (!a.quiet) {
        fmt::print("{}: reference of {} elements, 2 x {} rays, {:.1f} s; seeds differ by {:.4f} "
                   "(object-space relative L2) -> {}\n",
                   scene.name, ref.solution.stats.leaves, a.options.rays, ref.seconds,
                   ref.object_error.relative_l2, dir.string());
    }
    return 0;
}

CLI::App* add_info_command(CLI::App& app, InfoArgs& a) {
    auto* cmd = app.add_subcommand(
        "info", "information measures of a scene's patches (entropies, mutual information)");
    cmd->add_option("scene", a.scene,
                    "bundled scene name, scene .json, .obj, or a solution's .vtp (its leaves)")
        ->required();
    cmd->add_option("--scene", a.solution_scene, "with a .vtp: the scene it solves (its name)");
    cmd->add_option("--method", a.method, "local (rays from each patch) or global (lines through "
                                          "the bounding sphere)")
        ->capture_default_str();
    cmd->add_option("--lines", a.lines, "local rays in all, or global lines")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--seed", a.seed, "random seed")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_flag("--json", a.json, "machine-readable output");
    return cmd;
}

namespace {

// The discretisation `hmcr info` measures: a scene's patches, or a solution's leaves.
struct InfoTarget {
    std::string label;
    PatchSet patches;
};

InfoTarget info_target(const InfoArgs& a) {
    if (fs::path(a.scene).extension() != ".vtp") {
        const Scene scene = load_scene(a.scene, SceneUse::geometry);
        return {scene.name, build_patch_set(scene.mesh)};
    }
    const std::string name =
        a.solution_scene.empty() ? fs::path(a.scene).stem().string() : a.solution_scene;
    return {name + " (leaves of " + fs::path(a.scene).filename().string() + ")",
            leaf_patches(read_vtp(a.scene))};
}

void print_info_table(const InfoTarget& t, const InformationMeasures& m, double seconds) {
    fmt::print("{}: {} patches, {} {} lines, {} rays ({} open), {:.1f} s; bits, +- one standard "
               "error, bias to subtract (1/n extrapolation)\n",
               t.label, t.patches.patches.size(), m.lines, line_method_name(m.method), m.samples,
               m.samples_open, seconds);
    const std::pair<const char*, InformationMeasures::Value> rows[] = {
        {"H_P   positional entropy", m.h_p},     {"H_S   visibility entropy", m.h_s},
        {"I_S   mutual information", m.i_s},     {"H_J   joint entropy", m.h_j},
        {"I^c_S continuous mutual information", m.i_cs},
        {"I^c_S - I_S discretisation error", m.discretisation_error}};
    for (const auto& [name, v] : rows) {
        fmt::print("  {:<38} {:10.5f} +- {:.5f}   bias {:+.5f}\n", name, v.estimate,
                   v.standard_error, v.bias);
    }
}

// The measures describe a closed scene's channel, with every row of F sampled.
void warn_info_assumptions(const InformationMeasures& m, double open, std::size_t patches) {
    if (open > 0.01) {
        fmt::print(stderr,
                   "hmcr: warning: {:.1f}% of the rays leave the scene or hit a back face; the "
                   "measures assume a closed scene (rows of F summing to 1)\n",
                   100 * open);
    }
    if (std::abs(m.i_s.bias) > m.i_s.standard_error) {
        fmt::print(stderr,
                   "hmcr: warning: I_S has not converged: its plug-in bias (about {:+.4f} bits, "
                   "likely more) exceeds its standard error; raise --lines\n",
                   m.i_s.bias);
    }
    if (m.patches_unsampled > 0) {
        fmt::print(stderr,
                   "hmcr: warning: no line crossed {} of the {} patches; their rows of F are "
                   "missing (use more lines)\n",
                   m.patches_unsampled, patches);
    }
}

}  // namespace

int run_info(const InfoArgs& a) {
    LineOptions o;
    o.method = parse_line_method(a.method);
    o.lines = a.lines;
    o.seed = a.seed;
    if (a.lines < 16) throw std::invalid_argument("lines must be at least 16");
    const InfoTarget target = info_target(a);
    const auto start = std::chrono::steady_clock::now();
    const InformationMeasures m = scene_information(target.patches, o);
    const double seconds = seconds_since(start);
    const double open = double(m.samples_open) / double(std::max<std::size_t>(1, m.samples));
    if (a.json) {
        nlohmann::json j = to_json(m);
        j["open_fraction"] = open;
        j["scene"] = target.label;
        j["patches"] = target.patches.patches.size();
        j["seconds"] = seconds;
        fmt::print("{}\n", j.dump(2));
    } else {
        print_info_table(target, m, seconds);
    }
    warn_info_assumptions(m, open, target.patches.patches.size());
    return 0;
}

CLI::App* add_study_command(CLI::App& app, StudyArgs& a) {
    auto* cmd = app.add_subcommand(
        "study", "every oracle x budget x seed against a reference: tables, images, plots");
    StudyOptions& o = a.options;
    cmd->add_option("scene", o.scene, "bundled scene name, scene .json, or .obj")->required();
    cmd->add_option("--reference", o.reference, "folder written by `hmcr reference`")->required();
    cmd->add_option("--budgets", a.budgets, "leaf counts, comma-separated")->required();
    cmd->add_option("--oracles", a.oracles, "comma-separated names, or all")->capture_default_str();
    cmd->add_option("--seeds", o.seeds, "seeds per cell")->capture_default_str();
    cmd->add_option("--first-seed", o.first_seed, "the first seed")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--rays", o.rays, "rays per solve")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--lines", o.lines, "N_s")->capture_default_str();
    cmd->add_option("--budget-tolerance", o.budget_tolerance, "relative")->capture_default_str();
    cmd->add_option("--samples", o.samples_per_axis, "n x n rays per pixel")->capture_default_str();
    cmd->add_option("--threads", o.threads, "worker threads, 0 = all")->capture_default_str();
    cmd->add_option("-o,--output", o.output, "output folder (rerunning resumes)")->required();
    cmd->add_flag("-q,--quiet", a.quiet, "print only errors");
    return cmd;
}

namespace {

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

std::size_t parse_budget(const std::string& text) {
    const auto count = parse_count(text);
    if (!count || *count == 0) {
        throw std::invalid_argument("budgets: '" + text + "' is not a positive leaf count");
    }
    return std::size_t(*count);
}

void print_study_progress(const StudyProgress& p) {
    using Stage = StudyProgress::Stage;
    const std::string where = fmt::format("hmcr study [{}/{}] {}", p.cell_index + 1, p.cell_count,
                                          p.cell);
    const std::string left = p.remaining_seconds >= 0
                                 ? fmt::format(", about {:.0f} s left", p.remaining_seconds)
                                 : std::string();
    switch (p.stage) {
        case Stage::kSkipped: fmt::print(stderr, "{}: done before, skipped\n", where); break;
        case Stage::kProbe:
            fmt::print(stderr, "{}: probe {}: epsilon {:.4g} -> {} leaves\n", where, p.probe,
                       p.last_probe.epsilon, p.last_probe.leaves);
            break;
        case Stage::kMeasuring: fmt::print(stderr, "{}: rendering and measuring\n", where); break;
        case Stage::kDone:
            fmt::print(stderr, "{}: done ({:.0f} s elapsed{})\n", where, p.elapsed_seconds, left);
            break;
        case Stage::kFailed:
            fmt::print(stderr, "{}: budget not reached, recorded as failed{}\n", where, left);
            break;
    }
}

}  // namespace

int run_study_command(StudyArgs& a) {
    for (const auto& b : split_commas(a.budgets)) a.options.budgets.push_back(parse_budget(b));
    a.options.oracles = split_commas(a.oracles);
    run_study(a.options, a.quiet ? StudyProgressFn{} : StudyProgressFn(print_study_progress));
    if (!a.quiet) fmt::print("study written to {}\n", a.options.output.string());
    return 0;
}

}  // namespace hmcr
