// SPDX-License-Identifier: Apache-2.0
// `hmcr error SOLUTION.vtp --reference DIR`: a study's metrics for one solution
// (studies/reference_measure.h): the object error with its standard error, each view's RMSE
// and PSNR, the share of its area finer than the reference resolves and the patches that hold
// the most of its squared error. The solution may be hmcr's or another program's (`--foreign`:
// the arrays of viz/foreign_solution.h).
#include <fmt/core.h>

#include <memory>

#include "app/command.h"
#include "app/scene_input.h"
#include "common/atomic_file.h"
#include "common/json_fields.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "common/text_file.h"
#include "meshes/patch_mesh.h"
#include "studies/object_error_json.h"
#include "studies/reference_measure.h"
#include "viz/foreign_solution.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

struct ErrorArgs {
    std::string solution, reference, scene, output;
    bool foreign = false;
    int samples = 2;
    bool quiet = false;
    SceneFlags scene_flags;
};

// The scene the reference was made of (reference.json's "reference.scene_file"), for a command
// line without --scene.
std::string reference_scene(const std::filesystem::path& dir) {
    return read_json_file(dir / "reference.json", [&](const nlohmann::json& j) {
        const nlohmann::json& r = json_member(j, {"reference"});
        const auto file = r.find("scene_file");
        if (file == r.end()) {
            throw InputError("the reference does not record its scene file: give --scene");
        }
        return json_string(*file, "reference.scene_file");
    });
}

ShadedMesh read_measured(const ErrorArgs& a, const Scene& scene) {
    if (!a.foreign) return read_solution(a.solution, scene).mesh;
    ShadedMesh m = read_foreign_solution(a.solution, scene.mesh.n_faces());
    const FaceMaterials materials(scene.mesh);
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        const auto f = scene.mesh.face_handle(m.patch_id[c]);
        if (m.side[c] == kBack && materials.back_index(f) == kOneSided) {
            throw InputError(a.solution, fmt::format("cell {} is on the back of patch {}, which "
                                                     "is one-sided in scene {}",
                                                     c, m.patch_id[c], quote(scene.name)));
        }
    }
    return m;
}

nlohmann::json errors_json(const ErrorArgs& a, const SolutionErrors& e) {
    nlohmann::json views = nlohmann::json::object();
    for (const auto& [name, v] : e.views) views[name] = v;
    return {{"solution", a.solution},        {"reference", a.reference},
            {"samples_per_axis", a.samples}, {"object_error", object_error_json(e.object)},
            {"finer_share", e.finer_share},  {"views", views}};
}

void print_errors(const Scene& scene, const SolutionErrors& e) {
    const ObjectError& o = e.object;
    if (std::isnan(o.relative_l2)) {
        fmt::print("object error: not measured (a traced reference has neither mesh nor points)\n");
    } else {
        fmt::print("object error: {:.5f}", o.relative_l2);
        if (!std::isnan(o.standard_error)) fmt::print(" +- {:.5f}", o.standard_error);
        fmt::print(" ({} samples; {} unmatched, {} on unlit backs, {} found nearest)\n", o.samples,
                   o.unmatched, o.unlit, o.nearest);
    }
    if (!std::isnan(e.finer_share)) {
        fmt::print("finer than the reference resolves: {:.1f}% of the area\n", 100 * e.finer_share);
    }
    for (const View& v : scene.views) {
        const ImageErrors& i = e.views.at(v.name);
        fmt::print("view {}: RMSEa {:.3f}, RMSEp {:.3f}, PSNRa {:.2f} dB, PSNRp {:.2f} dB\n",
                   v.name, i.rmse_a, i.rmse_p, i.psnr_a, i.psnr_p);
    }
    if (!o.largest.empty()) {
        fmt::print("largest shares of the squared error:");
        for (const PatchError& p : o.largest) {
            fmt::print(" patch {}{} {:.1f}%", p.patch, p.side == kBack ? " (back)" : "",
                       100 * p.share);
        }
        fmt::print("\n");
    }
}

int run_error(ErrorArgs& a) {
    if (a.samples < 1 || a.samples > 16) throw InputError("samples must be in 1..16");
    const std::filesystem::path dir(a.reference);
    const std::string scene_name = a.scene.empty() ? reference_scene(dir) : a.scene;
    const Scene scene = load_scene_reporting(scene_name, a.quiet, SceneUse::solve, a.scene_flags);
    std::optional<OutputSet> out;
    if (!a.output.empty()) {
        if (std::filesystem::path(a.output).extension() != ".json") {
            throw InputError("output must be a .json file, got " + quote(a.output));
        }
        std::vector<std::filesystem::path> inputs = scene.inputs;
        inputs.emplace_back(a.solution);
        inputs.push_back(dir / "reference.json");
        refuse_overwriting({a.output}, inputs);
        out.emplace(std::vector<std::filesystem::path>{a.output});
    }
    const ShadedMesh solution = read_measured(a, scene);
    const LoadedReference reference = load_reference(dir, scene);
    const SolutionErrors e = measure_solution(reference, solution, scene, a.samples);
    if (!a.quiet) print_errors(scene, e);
    if (out) {
        write_text_atomically(out->temp(a.output), errors_json(a, e).dump(2) + "\n");
        out->commit();
    }
    return 0;
}

}  // namespace

Command error_command(CLI::App& app) {
    auto a = std::make_shared<ErrorArgs>();
    auto* cmd = app.add_subcommand(
        "error", "a study's metrics for one solution against a reference (object error, images)");
    cmd->add_option("solution", a->solution, "the solution's .vtp")->required();
    cmd->add_option("--reference", a->reference, "a reference folder of any kind")->required();
    cmd->add_option("--scene", a->scene,
                    "the scene it solves (default: the scene the reference was made of)");
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_flag("--foreign", a->foreign,
                  "the .vtp is another program's: polygons, point Radiosity and cell PatchId "
                  "(docs/design.md §11.4)");
    cmd->add_option("--samples", a->samples, "n x n rays per pixel of the images")
        ->capture_default_str();
    cmd->add_option("-o,--output", a->output, "also write the metrics to this .json");
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a] { return run_error(*a); }};
}

}  // namespace hmcr
