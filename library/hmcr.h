// SPDX-License-Identifier: Apache-2.0
// The common path of a program that uses hmcr as a library (docs/library.md): load a scene, take
// its settings, solve it, write its solution as `hmcr solve` does, and measure it against a
// reference as `hmcr error` does. Installed as "hmcr/hmcr.h"; every call is one of the layers'
// (the headers it includes), for the rest of what they offer.
#pragma once

#include <filesystem>
#include <string>

#include "common/progress.h"
#include "meshes/scene.h"
#include "radiosity/solver.h"
#include "radiosity/solver_options.h"
#include "studies/reference_measure.h"

namespace hmcr {

// A bundled scene's name, a scene .json or a mesh file, loaded, repaired and checked as `hmcr
// solve` loads it. Throws InputError "file:line: what".
Scene load(const std::string& name_or_path, const LoadOptions& options = {});

// The settings of a solve of the scene: the defaults, then its scene file's "solver" object,
// checked. Change them, then solve.
SolverOptions settings_of(const Scene& scene);

// One solve of the scene with its views (refine-then-freeze, as `hmcr solve` at the options'
// epsilon). The same bits for the same settings on any thread count.
Solution solve(const Scene& scene, const SolverOptions& options,
               Progress& progress = no_progress());

// The .vtp `hmcr solve` writes for the same scene and settings, written atomically.
void write(const std::filesystem::path& vtp, const Solution& solution, const Scene& scene);

// What `hmcr error SOLUTION.vtp --reference DIR` measures: the object error with its standard
// error and every view's image errors, of the solution as its file holds it.
SolutionErrors measure(const Solution& solution, const Scene& scene,
                       const std::filesystem::path& reference, int samples_per_axis = 2);

}  // namespace hmcr
