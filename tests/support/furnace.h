// SPDX-License-Identifier: Apache-2.0
// The furnace's exact test (docs/design.md §8.2): every patch of a closed box that emits E and
// reflects rho everywhere has B = E (1 - rho^(K+1)) / (1 - rho) after K iterations, whatever
// the mesh.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>

#include "meshes/patch_mesh.h"
#include "radiosity/solver.h"

namespace hmcr::test {

// E (1 - rho^(K+1)) / (1 - rho): the furnace's B after K iterations.
inline double furnace_value(double rho, double e, std::size_t iterations) {
    return e * (1 - std::pow(rho, double(iterations + 1))) / (1 - rho);
}

// Solves `mesh` (such a box) with options(seed) for the seeds 1..seeds, passing each solution
// to `check` (a test's guards), expects the same K (the iterations the values hold) for every
// seed, and t-tests every patch's B over the seeds against the K-bounce value, with Bonferroni
// over the patches. Returns K. `inputs` are every solve's (the views of view importance).
std::size_t expect_furnace_per_patch(const PatchMesh& mesh, double rho, double e, int seeds,
                                     const std::function<SolverOptions(std::uint64_t)>& options,
                                     const std::function<void(const Solution&)>& check = {},
                                     const SolveInputs& inputs = {});

}  // namespace hmcr::test
