// SPDX-License-Identifier: Apache-2.0
// solve_scene SCENE RAYS OUT.vtp: what `hmcr solve SCENE --rays RAYS -o OUT.vtp` writes, from
// hmcr's installed library by its common path, "hmcr/hmcr.h" (tests/install/install_test.sh
// compares the bytes).
#include <exception>
#include <iostream>
#include <string>

#include "hmcr/hmcr.h"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: solve_scene SCENE RAYS OUT.vtp\n";
        return 2;
    }
    try {
        const hmcr::Scene scene = hmcr::load(argv[1]);
        hmcr::SolverOptions options = hmcr::settings_of(scene);
        options.rays = std::stoull(argv[2]);
        const hmcr::Solution solution = hmcr::solve(scene, options);
        hmcr::write(argv[3], solution, scene);
    } catch (const std::exception& e) {
        std::cerr << "solve_scene: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
