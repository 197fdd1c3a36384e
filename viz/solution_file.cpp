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
    return shaded;
}

SolutionFile read_solution(const std::filesystem::path& vtp) {
    SolutionFile file;
    file.mesh = read_vtp(vtp, &file.meta);
    return file;
}

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
    return file;
}

}  // namespace hmcr
