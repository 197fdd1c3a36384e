// SPDX-License-Identifier: Apache-2.0
#include "studies/reference.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/atomic_file.h"
#include "common/file_names.h"
#include "common/json_fields.h"
#include "common/rgb_json.h"
#include "common/text_file.h"
#include "meshes/patch_mesh.h"
#include "studies/point_error.h"
#include "studies/point_reference.h"
#include "viz/renderer.h"
#include "viz/shaded_tracer.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

Solution solve_uniform(const Scene& scene, const ReferenceOptions& o, std::uint64_t seed,
                       Progress& progress, const Ranks& ranks) {
    SolverOptions s = o.solver;
    s.uniform_max_area = o.max_area;
    s.seed = seed;
    s.min_area = 0;  // the uniform mesh decides; limits only cap the depth
    s.max_depth = 24;
    return solve(scene.mesh, s, {}, progress, ranks);  // a fixed mesh: no importance, no views
}

}  // namespace

// Read from the mesh's material table: the patch set (208 bytes a patch) is not needed for it.
ObjectErrorOptions reflected_error_options(const PatchMesh& mesh) {
    ObjectErrorOptions o;
    const FaceMaterials materials(mesh);
    o.emission.reserve(mesh.n_faces());
    for (auto f : mesh.faces()) {
        const OpenMesh::Vec3d& e = materials[f].emission;
        o.emission.emplace_back(e[0], e[1], e[2]);
    }
    for (auto f : mesh.faces()) {
        const std::uint32_t back = materials.back_index(f);
        if (back == kOneSided) continue;
        o.back_emission.resize(mesh.n_faces(), Rgb::Zero());
        const OpenMesh::Vec3d& e = materials.table()[back].emission;
        o.back_emission[std::size_t(f.idx())] = Rgb(e[0], e[1], e[2]);
    }
    return o;
}

Reference compute_reference(const Scene& scene, const ReferenceOptions& o, Progress& progress,
                            const Ranks& ranks) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t seed = o.solver.seed;
    Reference ref;
    progress.stage("solving with seed " + std::to_string(seed));
    ref.solution = solve_uniform(scene, o, seed, progress, ranks);
    ref.mesh = shade(ref.solution, o.crease_degrees);
    progress.stage("solving with seed " + std::to_string(seed + 1) + " for the convergence report");
    const Solution second = solve_uniform(scene, o, seed + 1, progress, ranks);
    const ShadedMesh second_mesh = shade(second, o.crease_degrees);
    ref.truncation = truncation_bias(ref.solution);
    ref.seed_difference =
        (reflected_power(*second.hierarchy) - ref.truncation.reflected).cwiseAbs() /
        ref.truncation.reflected.cwiseMax(1e-300);
    progress.stage("comparing the two seeds");
    const ShadedTracer first_tracer(ref.mesh), second_tracer(second_mesh);
    ref.object_error = object_space_error(second_tracer, second_mesh, ref.mesh,
                                          reflected_error_options(scene.mesh));
    const RenderOptions render_options{o.samples_per_axis};
    for (const View& v : scene.views) {
        progress.stage("rendering view " + v.name);
        Image image = render(first_tracer, v, render_options);
        const double exposure = exposure_from(image);
        const Image other = render(second_tracer, v, render_options);
        ref.view_errors[v.name] =
            image_errors(quantise(other, exposure), quantise(image, exposure));
        ref.views[v.name] = {std::move(image), exposure};
    }
    if (const CheckSize check = check_size(o, ref.solution.stats.leaves); check.points > 0) {
        progress.stage("checking the mesh against points");
        const PathTracer tracer(diffuse_patch_set(scene), PathOptions{});
        PointReferenceOptions sampling;
        sampling.points = check.points;
        sampling.paths = check.paths;
        sampling.seed = seed;
        std::uint64_t rays = 0;
        const PointTarget points =
            point_target(estimate_reference_points(scene, tracer, sampling, progress, ranks, rays),
                         tracer.patches());
        ref.discretisation = point_object_error(first_tracer, ref.mesh, points);
        ref.check_paths = check.paths;
    }
    ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return ref;
}

CheckSize check_size(const ReferenceOptions& o, std::uint64_t elements) {
    CheckSize c;
    c.points = o.check_points.value_or(std::min(kMostCheckPoints, 4 * elements));
    if (c.points == 0) return c;
    // A path casts about 5 rays on the bundled rooms; two seeds.
    const double paths = double(o.solver.rays) / (10.0 * 5 * 2 * double(c.points));
    c.paths = std::uint64_t(std::clamp(paths, 16.0, 1024.0));
    return c;
}

std::string scene_file(const Scene& scene) {
    if (scene.source.empty()) return "";  // a program's own polygons (meshes/polygon_soup.h)
    return std::filesystem::absolute(scene.source).lexically_normal().string();
}

std::vector<std::filesystem::path> reference_files(const std::filesystem::path& dir,
                                                   const Scene& scene) {
    std::vector<std::filesystem::path> files{dir / "reference.vtp", dir / "reference.json"};
    for (const View& v : scene.views) {
        files.push_back(named_file(dir / "views", v.name, ".pfm"));
        files.push_back(named_file(dir / "views", v.name, ".png"));
    }
    return files;
}

void write_reference(OutputSet& out, const std::filesystem::path& dir, const Scene& scene,
                     const Reference& ref, const ReferenceOptions& o, nlohmann::json summary) {
    const SolveStats& st = ref.solution.stats;
    write_solution(out.temp(dir / "reference.vtp"), ref.mesh, ref.solution, scene_identity(scene),
                   double(st.iterations.size()));
    nlohmann::json views = nlohmann::json::object(), errors = nlohmann::json::object();
    for (const auto& [name, view] : ref.views) {
        write_pfm(out.temp(named_file(dir / "views", name, ".pfm")), view.image);
        write_png(out.temp(named_file(dir / "views", name, ".png")), view.image, view.exposure);
        views[name] = {{"exposure", view.exposure}};
        errors[name] = ref.view_errors.at(name);
    }
    summary["reference"] = {
        {"max_area_m2", o.max_area},
        {"rays_per_seed", o.solver.rays},
        {"seeds", {o.solver.seed, o.solver.seed + 1}},
        {"samples_per_axis", o.samples_per_axis},
        {"views", views},
        {"convergence",
         {{"what", "the second seed's solution measured against the first"},
          {"object_space_relative_l2", ref.object_error.relative_l2},
          {"object_space_samples", ref.object_error.samples},
          {"object_space_unmatched", ref.object_error.unmatched},
          {"views", errors}}},
        {"truncation",
         {{"what",
           "the reflected power the unshot power would still add, U r / (1 - r) with r "
           "the last iteration's decay, relative to the reflected power, per channel "
           "(R, G, B); seed_difference: the seeds' reflected powers' relative difference"},
          {"stop", o.solver.stop},
          {"unshot_power", rgb_json(ref.truncation.unshot)},
          {"decay", rgb_json(ref.truncation.decay)},
          {"relative_bias", rgb_json(ref.truncation.relative)},
          {"seed_difference", rgb_json(ref.seed_difference)}}},
        {"discretisation",
         {{"what",
           "the first seed's solution measured against points traced independently of any "
           "mesh (an object error, relative to the reflected radiosity, with its standard "
           "error): what the uniform mesh and its noise leave out"},
          {"check_points", ref.discretisation.samples},
          {"check_paths", ref.check_paths},
          {"relative_l2", ref.discretisation.relative_l2},
          {"standard_error", ref.discretisation.standard_error}}},
        {"seconds", ref.seconds},
        {"scene", scene.name},
        {"scene_file", scene_file(scene)}};
    if (scene.source.empty()) summary["reference"].erase("scene_file");
    write_text_atomically(out.temp(dir / "reference.json"), summary.dump(2) + "\n");
}

std::map<std::string, double> read_reference_exposures(const std::filesystem::path& dir) {
    return read_json_file(dir / "reference.json", [](const nlohmann::json& j) {
        std::map<std::string, double> exposure;
        const std::string views = "reference.views";
        const nlohmann::json& all = json_object(json_member(j, {"reference", "views"}), views);
        for (const auto& [view, v] : all.items()) {
            check_name(view, "view");  // as a scene file's views are
            const std::string path = json_path(views, view);
            const double e = json_number(json_member(v, {"exposure"}, path), path + ".exposure");
            if (!(e > 0 && std::isfinite(e))) {
                throw InputError(
                    fmt::format("view {}: exposure {} is not a positive number", quote(view), e));
            }
            exposure[view] = e;
        }
        return exposure;
    });
}

}  // namespace hmcr
