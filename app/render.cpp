// SPDX-License-Identifier: Apache-2.0
// `hmcr render SOLUTION.vtp --scene SCENE`: an image of a solution from one of the scene's views.
#include <memory>

#include "app/command.h"
#include "app/exposure.h"
#include "app/scene_input.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "viz/renderer.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

struct RenderArgs {
    std::string solution;     // .vtp
    std::string scene;        // for the view
    std::string view;         // empty: the scene's first view
    std::string output;       // .png
    std::string pfm;          // optional linear image
    ExposureChoice exposure;  // fixed, from a reference folder, or from the image
    RenderOptions options;
    SceneFlags scene_flags;
    bool quiet = false;
};

// Every file the render reads, and the outputs checked (and locked) before any work.
std::vector<std::filesystem::path> check_outputs(const RenderArgs& a, const Scene& scene) {
    if (std::filesystem::path(a.output).extension() != ".png") {
        throw InputError("output must be a .png file, got " + quote(a.output));
    }
    if (!a.pfm.empty() && std::filesystem::path(a.pfm).extension() != ".pfm") {
        throw InputError("pfm must be a .pfm file, got " + quote(a.pfm));
    }
    std::vector<std::filesystem::path> inputs = scene.inputs;
    inputs.emplace_back(a.solution);
    for (const auto& in : exposure_inputs(a.exposure)) inputs.push_back(in);
    std::vector<std::filesystem::path> outputs{a.output};
    if (!a.pfm.empty()) outputs.emplace_back(a.pfm);
    refuse_overwriting(outputs, inputs);
    return outputs;
}

int run_render(const RenderArgs& a) {
    if (a.options.samples_per_axis < 1 || a.options.samples_per_axis > 16) {
        throw InputError("samples must be in 1..16");
    }
    check_exposure(a.exposure);
    const Scene scene = load_scene_reporting(a.scene, a.quiet, SceneUse::solve, a.scene_flags);
    warn_specular(scene, a.quiet, SpecularUse::render);
    OutputSet out(check_outputs(a, scene));
    const View& view = find_view(scene, a.view);
    const double exposure = fixed_exposure(a.exposure, view.name);
    const ShadedMesh mesh = read_solution(a.solution, scene).mesh;
    const Image image = render(mesh, view, a.options);
    const double e = image_exposure(exposure, image);
    write_png(out.temp(a.output), image, e);
    if (!a.pfm.empty()) write_pfm(out.temp(a.pfm), image);
    out.commit();
    warn_if_black(image, e, a.output, a.scene, view.name, a.quiet);
    return 0;
}

}  // namespace

Command render_command(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    auto* cmd = app.add_subcommand("render", "render a solution (.vtp) from a view of its scene");
    cmd->add_option("solution", a->solution, "the solution's .vtp")->required();
    cmd->add_option("--scene", a->scene, "the scene it solves (for its views)")->required();
    add_view_flag(*cmd, a->view);
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_option("-o,--output", a->output, "8-bit sRGB .png")->required();
    cmd->add_option("--pfm", a->pfm, "also write the linear radiance as .pfm");
    cmd->add_option("--samples", a->options.samples_per_axis, "n x n rays per pixel")
        ->capture_default_str();
    add_exposure_flags(*cmd, a->exposure);
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a, cmd] {
                note_exposure_given(*cmd, a->exposure);
                return run_render(*a);
            }};
}

}  // namespace hmcr
