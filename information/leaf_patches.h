// SPDX-License-Identifier: Apache-2.0
// The leaves of a solution as a discretisation of their own (docs/design.md §7: "measures of a
// discretisation can be taken ... for the leaves of a solution").
#pragma once

#include <cstddef>
#include <vector>

#include "radiosity/shaded_mesh.h"
#include "rays/patch.h"

namespace hmcr {

// One patch per cell of a solution's mesh: the cell's polygon without the vertices it carries
// in the middle of its edges (T-junction points of finer neighbours), i.e. the leaf's own
// triangle or quad. Material data is left at zero: the information measures need geometry only.
// Throws std::invalid_argument for a cell that is not a triangle or quad once reduced.
// On a higher-order basis, one patch per leaf, whatever its sub-cells: the leaf's corners are
// its points at the corners of its local coordinates' unit square or triangle.
PatchSet leaf_patches(const ShadedMesh& mesh);

// The first cell of each leaf, in leaf order: every cell on the constant basis, where each leaf
// is one.
std::vector<std::size_t> leaf_first_cells(const ShadedMesh& mesh);

}  // namespace hmcr
