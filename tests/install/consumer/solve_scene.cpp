// SPDX-License-Identifier: Apache-2.0
// solve_scene SCENE RAYS OUT.vtp: what `hmcr solve SCENE --rays RAYS -o OUT.vtp` writes, from
// hmcr's installed library (tests/install/install_test.sh compares the bytes).
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "hmcr/meshes/scene.h"
#include "hmcr/radiosity/solver.h"
#include "hmcr/radiosity/solver_settings.h"
#include "hmcr/viz/solution_file.h"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: solve_scene SCENE RAYS OUT.vtp\n";
        return 2;
    }
    try {
        const hmcr::Scene scene = hmcr::load_scene(argv[1]);
        hmcr::SolverOptions options;
        hmcr::apply_scene_settings(scene.solver_defaults, scene.source.string(), options);
        options.rays = std::stoull(argv[2]);
        const hmcr::Solution solution = hmcr::solve(scene.mesh, options, {scene.views});
        hmcr::write_solution(argv[3], solution, scene, hmcr::kCreaseDegrees,
                             double(solution.stats.iterations.size()));
    } catch (const std::exception& e) {
        std::cerr << "solve_scene: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
