// SPDX-License-Identifier: Apache-2.0
#include "viz/solution_file.h"

#include <fmt/format.h>

#include "viz/vtk_import.h"

namespace hmcr {

SceneIdentity scene_identity(const Scene& scene) {
    return {scene.name, scene.mesh.n_faces(), geometry_hash(scene.mesh)};
}

VtpMetadata vtp_metadata(const Solution& solution, const SceneIdentity& scene, double time_value) {
    const SolveStats& st = solution.stats;
    const bool uniform = solution.options.uniform_max_area > 0;
    return {uniform ? "uniform" : std::string(solution.options.oracle->name()),
            uniform ? 0 : st.epsilon,
            uniform ? 0 : std::uint64_t(solution.options.lines),
            st.rays,
            solution.options.seed,
            st.faces,
            st.leaves,
            st.iterations.size(),
            time_value,
            scene.name,
            scene.patches,
            scene.geometry_hash,
            std::string(name(solution.options.link_weight)),
            std::string(name(solution.options.clustering))};
}

ShadedMesh shade(const Solution& solution, double crease_degrees) {
    ShadedMesh mesh = build_shaded_mesh(*solution.hierarchy, crease_degrees);
    set_cluster_ids(mesh, solution.cluster_of_side());
    return mesh;
}

void write_solution(const std::filesystem::path& vtp, const ShadedMesh& shaded,
                    const Solution& solution, const SceneIdentity& scene, double time_value) {
    write_vtp(vtp, shaded, vtp_metadata(solution, scene, time_value));
}

ShadedMesh write_solution(const std::filesystem::path& vtp, const Solution& solution,
                          const Scene& scene, double crease_degrees, double time_value) {
    ShadedMesh shaded = shade(solution, crease_degrees);
    write_solution(vtp, shaded, solution, scene_identity(scene), time_value);
    return as_stored(std::move(shaded));
}

ShadedMesh as_stored(ShadedMesh mesh) {
    // Through a volatile float: GCC 12's vectoriser folds a double-float-double round trip on
    // Eigen's arrays into nothing for some of the channels (docs/decisions.md).
    const auto as_float = [](Rgb& b) {
        for (int k = 0; k < 3; ++k) {
            const volatile float f = float(b[k]);
            b[k] = f;
        }
    };
    for (Rgb& b : mesh.point_radiosity) as_float(b);
    for (Rgb& b : mesh.element_radiosity) as_float(b);
    return mesh;
}

SolutionFile read_solution(const std::filesystem::path& vtp) {
    SolutionFile file;
    file.mesh = read_vtp(vtp, &file.meta);
    return file;
}

namespace {

// The solution's backs are the scene's: a back cell only on a two-sided patch, and one on every
// patch whose back emits (its root is made at the start, docs/design.md §1.3).
void check_sides(const std::filesystem::path& vtp, const ShadedMesh& m, const Scene& scene) {
    const FaceMaterials materials(scene.mesh);
    std::vector<bool> has_back(scene.mesh.n_faces(), false);
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        if (m.side[c] != kBack) continue;
        const int p = m.patch_id[c];
        if (materials.back_index(OpenMesh::FaceHandle(p)) == kOneSided) {
            throw InputError(vtp.string(),
                             fmt::format("cell {} is the back of patch {}, which is one-sided in "
                                         "scene {} (a solution of it with other sides?)",
                                         c, p, quote(scene.name)));
        }
        has_back[std::size_t(p)] = true;
    }
    for (const auto f : scene.mesh.faces()) {
        const std::uint32_t back = materials.back_index(f);
        if (back == kOneSided || has_back[std::size_t(f.idx())]) continue;
        if (materials.table()[back].emission.max() > 0) {
            throw InputError(vtp.string(),
                             fmt::format("patch {} has no back cell, but its back emits in scene "
                                         "{} (a solution of it with other sides?)",
                                         f.idx(), quote(scene.name)));
        }
    }
}

}  // namespace

SolutionFile read_solution(const std::filesystem::path& vtp, const Scene& scene) {
    SolutionFile file = read_solution(vtp);
    const SceneIdentity id = scene_identity(scene);
    if (file.meta.patch_count != id.patches || file.meta.geometry_hash != id.geometry_hash) {
        throw InputError(
            vtp.string(),
            fmt::format("is a solution of scene {} ({} patches, "
                        "geometry {}), not of {} ({} patches, geometry {})",
                        quote(file.meta.scene), file.meta.patch_count, file.meta.geometry_hash,
                        quote(id.name), id.patches, id.geometry_hash));
    }
    check_sides(vtp, file.mesh, scene);
    return file;
}

}  // namespace hmcr
