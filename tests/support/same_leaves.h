// SPDX-License-Identifier: Apache-2.0
// Solutions that must be the same bit for bit (docs/design.md §9): any thread count, a setting
// that may not change them. One check, the leaves' ids and radiosity in order.
#pragma once

#include "meshes/patch_mesh.h"
#include "radiosity/hierarchy.h"
#include "radiosity/solver.h"

namespace hmcr::test {

// Expects the same leaves (ids, in order) with the same radiosity, bit for bit, and on a higher
// basis the same coefficients.
void expect_same_leaves(const Hierarchy& a, const Hierarchy& b);

// Solves `mesh` with `options` on 1 and on 2 threads and expects the same leaves and the same
// cluster leaves. Returns the one-thread solution.
Solution solve_on_one_and_two_threads(const PatchMesh& mesh, SolverOptions options,
                                      const SolveInputs& inputs = {});

}  // namespace hmcr::test
