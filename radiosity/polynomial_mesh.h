// SPDX-License-Identifier: Apache-2.0
// The leaves of a hierarchy solved on a higher-order basis as the output shows them
// (docs/design.md §5.9): each leaf on its own points, cut into n x n sub-cells, every point
// holding the leaf's polynomial there, and every cell what evaluates it anywhere inside.
#pragma once

#include <array>

#include "radiosity/basis.h"
#include "radiosity/hierarchy.h"
#include "radiosity/shaded_mesh.h"

namespace hmcr {

// The sub-cells along each edge of a leaf: 1 linear, 2 bilinear, 3 quadratic, 4 cubic (1 for
// the constant basis, which build_shaded_mesh draws otherwise).
int polynomial_subdivisions(Basis basis);

// The mesh of a hierarchy on a basis other than the constant: the leaves in canonical order,
// fronts before backs, each cut into polynomial_subdivisions(h.basis())^2 sub-squares (quad
// patches) or sub-triangles (triangle patches) on points of its own, not shared with its
// neighbours, so that the basis's jumps between leaves show. Every point's radiosity is the
// leaf's polynomial there; every cell has its leaf's mean, depth, patch, side, index and
// coefficients and its own area.
ShadedMesh build_polynomial_mesh(const Hierarchy& h);

// The radiosity of the polynomial with coefficient-major `coefficients` (3 K of them, as
// ShadedMesh::coefficients holds a cell's) on the square's (quad) or the triangle's basis, at
// local coordinates ab.
Rgb polynomial_radiosity(Basis basis, bool quad, const double* coefficients, const Vec2& ab);
// The same for a cell of a mesh on a higher-order basis: its leaf's polynomial at ab (a quad's
// basis for a cell of 4 points, a triangle's for one of 3).
Rgb polynomial_radiosity(const ShadedMesh& mesh, std::size_t cell, const Vec2& ab);

// What `mesh` shows at the point of cell `cell` with weights (1 - w1 - w2, w1, w2) of its points
// `points` (three of the cell's, a triangle of it): on the constant basis the blend of their
// Gouraud values; on a higher one the cell's polynomial at the blend of their local coordinates,
// exact where the patch's map is affine.
Rgb radiosity_at(const ShadedMesh& mesh, std::size_t cell, const std::array<std::size_t, 3>& points,
                 double w1, double w2);

}  // namespace hmcr
