// SPDX-License-Identifier: Apache-2.0
#include "library/hmcr.h"

#include "radiosity/shaded_mesh.h"
#include "radiosity/solver_settings.h"
#include "rays/patch.h"
#include "viz/solution_file.h"

namespace hmcr {

Scene load(const std::string& name_or_path, const LoadOptions& options) {
    return load_scene(name_or_path, options);
}

SolverOptions settings_of(const Scene& scene) {
    SolverOptions options;
    apply_scene_settings(scene.solver_defaults, scene.source.string(), options);
    return options;
}

Solution solve(const Scene& scene, const SolverOptions& options, Progress& progress) {
    return solve(build_patch_set(scene.mesh), options, SolveInputs{scene.views}, progress);
}

void write(const std::filesystem::path& vtp, const Solution& solution, const Scene& scene) {
    write_solution(vtp, solution, scene, kCreaseDegrees, double(solution.stats.iterations.size()));
}

SolutionErrors measure(const Solution& solution, const Scene& scene,
                       const std::filesystem::path& reference, int samples_per_axis) {
    const LoadedReference loaded = load_reference(reference, scene);
    return measure_solution(loaded, as_stored(shade(solution, kCreaseDegrees)), scene,
                            samples_per_axis);
}

}  // namespace hmcr
