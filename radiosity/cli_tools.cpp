#include "radiosity/cli_tools.h"

#include <fmt/core.h>

#include <fstream>

#include "radiosity/run_summary.h"
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

// The exposure a reference folder fixed for a view (reference.json).
double reference_exposure(const fs::path& dir, const std::string& view) {
    std::ifstream in(dir / "reference.json");
    if (!in) throw std::invalid_argument((dir / "reference.json").string() + ": cannot read it");
    const auto j = nlohmann::json::parse(in);
    const auto& views = j.at("reference").at("views");
    if (!views.contains(view)) {
        throw std::invalid_argument((dir / "reference.json").string() + ": no view '" + view + "'");
    }
    return views.at(view).at("exposure").get<double>();
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderArgs& a) {
    auto* cmd = app.add_subcommand("render", "render a solution (.vtp) from a view of its scene");
    cmd->add_option("solution", a.solution, "the solution's .vtp")->required();
    cmd->add_option("--scene", a.scene, "the scene it solves (for its views)")->required();
    cmd->add_option("--view", a.view, "view name (default: the scene's first)");
    cmd->add_option("-o,--output", a.output, "8-bit sRGB .png")->required();
    cmd->add_option("--pfm", a.pfm, "also write the linear radiance as .pfm");
    cmd->add_option("--samples", a.options.samples_per_axis, "n x n rays per pixel")
        ->capture_default_str();
    cmd->add_option("--exposure", a.exposure, "fixed exposure (default: from this image)");
    cmd->add_option("--reference", a.reference, "use the exposure of this reference folder");
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
    cmd->add_option("--rays", o.rays, "rays per seed")->capture_default_str();
    cmd->add_option("--seed", o.seed, "first seed (the second is seed + 1)")->capture_default_str();
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

}  // namespace hmcr
