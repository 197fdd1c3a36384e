// `hmcr render SOLUTION.vtp --scene SCENE`: an image of a solution from one of the scene's views.
#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "app/scene_input.h"
#include "app/command.h"
#include "common/output_paths.h"
#include "studies/reference.h"
#include "viz/renderer.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

struct RenderArgs {
    std::string solution;   // .vtp
    std::string scene;      // for the view
    std::string view;       // empty: the scene's first view
    std::string output;     // .png
    std::string pfm;        // optional linear image
    std::string reference;  // optional reference folder: its exposure for this view
    double exposure = 0;    // fixed exposure, when given
    bool exposure_given = false;
    RenderOptions options;
    SceneFlags scene_flags;
};

// The exposure a reference folder fixed for a view.
double reference_exposure(const std::filesystem::path& dir, const std::string& view) {
    const auto exposure = read_reference_exposures(dir);
    if (!exposure.count(view)) {
        throw InputError((dir / "reference.json").string(), "no view " + quote(view));
    }
    return exposure.at(view);
}

// Every file the render reads, and the outputs checked before any work.
void check_outputs(const RenderArgs& a, const Scene& scene) {
    if (std::filesystem::path(a.output).extension() != ".png") {
        throw InputError("output must be a .png file, got " + quote(a.output));
    }
    if (!a.pfm.empty() && std::filesystem::path(a.pfm).extension() != ".pfm") {
        throw InputError("pfm must be a .pfm file, got " + quote(a.pfm));
    }
    std::vector<std::filesystem::path> inputs = scene.inputs;
    inputs.push_back(a.solution);
    if (!a.reference.empty()) inputs.push_back(std::filesystem::path(a.reference) / "reference.json");
    std::vector<std::filesystem::path> outputs{a.output};
    if (!a.pfm.empty()) outputs.push_back(a.pfm);
    refuse_overwriting(outputs, inputs);
    for (const auto& out : outputs) prepare_output_file(out);
}

int run_render(const RenderArgs& a) {
    if (a.options.samples_per_axis < 1 || a.options.samples_per_axis > 16) {
        throw InputError("samples must be in 1..16");
    }
    if (a.exposure_given && !(a.exposure > 0 && std::isfinite(a.exposure))) {
        throw InputError(fmt::format("exposure must be a positive number, got {}", a.exposure));
    }
    const Scene scene = load_scene_reporting(a.scene, false, SceneUse::solve, a.scene_flags);
    check_outputs(a, scene);
    const View& view = find_view(scene, a.view);
    double exposure = a.exposure;
    if (!a.reference.empty()) exposure = reference_exposure(a.reference, view.name);
    const ShadedMesh mesh = read_solution(a.solution, scene).mesh;
    const Image image = render(mesh, view, a.options);
    if (!a.exposure_given && a.reference.empty()) exposure = exposure_from(image);
    write_png(a.output, image, exposure);
    if (!a.pfm.empty()) write_pfm(a.pfm, image);
    return 0;
}

}  // namespace

Command render_command(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    auto* cmd = app.add_subcommand("render", "render a solution (.vtp) from a view of its scene");
    cmd->add_option("solution", a->solution, "the solution's .vtp")->required();
    cmd->add_option("--scene", a->scene, "the scene it solves (for its views)")->required();
    cmd->add_option("--view", a->view, "view name (default: the scene's first)");
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_option("-o,--output", a->output, "8-bit sRGB .png")->required();
    cmd->add_option("--pfm", a->pfm, "also write the linear radiance as .pfm");
    cmd->add_option("--samples", a->options.samples_per_axis, "n x n rays per pixel")
        ->capture_default_str();
    auto* exposure =
        cmd->add_option("--exposure", a->exposure, "fixed exposure (default: from this image)");
    cmd->add_option("--reference", a->reference, "use the exposure of this reference folder")
        ->excludes(exposure);
    return {cmd, [a, exposure] {
                a->exposure_given = exposure->count() > 0;
                return run_render(*a);
            }};
}

}  // namespace hmcr
