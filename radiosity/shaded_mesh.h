// SPDX-License-Identifier: Apache-2.0
// The leaves of a solved hierarchy as a conforming polygon mesh with Gouraud vertex radiosity
// (docs/design.md §5), or on a higher-order basis as each leaf's polynomial on sub-cells of its
// own (radiosity/polynomial_mesh.h): what the VTK export and the image renderer draw.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "common/types.h"
#include "radiosity/basis.h"
#include "radiosity/hierarchy.h"

namespace hmcr {

// Patches meeting at this angle or more are not blended in the Gouraud values (degrees): the
// default of `--crease-angle`, references and studies.
inline constexpr double kCreaseDegrees = 30;

// Plain arrays in VTK's layout: cell c is connectivity[offsets[c] .. offsets[c + 1]). The fronts'
// cells and points come first, then those of the backs that exist (docs/design.md §5.3): the two
// sides of a patch share no point, so neither side's values blend into the other's.
struct ShadedMesh {
    std::vector<Vec3> points;
    std::vector<Rgb> point_radiosity;      // Gouraud value of each point, W/m^2
    std::vector<std::int64_t> offsets{0};  // cell_count() + 1 entries
    std::vector<std::int64_t> connectivity;

    // One cell per leaf (on a higher-order basis, n x n sub-cells per leaf, leaf_index says
    // whose), in the canonical leaf order of Hierarchy::for_each_leaf.
    std::vector<Rgb> element_radiosity;  // the leaf's B (its mean on a higher-order basis)
    std::vector<int> hierarchy_level;    // the leaf's depth
    std::vector<int> patch_id;
    std::vector<double> element_area;  // the cell's area
    // The side of its patch each cell shows: kFront, or kBack for the reversed polygons of a
    // two-sided patch's back, which follow all the fronts.
    std::vector<std::uint8_t> side;
    // The cluster leaf each cell's side belongs to, -1 where the side is in the mesh itself
    // (docs/design.md §2.7); empty without clustering.
    std::vector<std::int32_t> cluster_id;

    // The basis the leaves' radiosity is a polynomial on. The arrays below are empty on the
    // constant basis; on another, B at a point of a cell is
    //   sum_k coefficients[cell_stride() * cell + 3 k + channel] * psi_k(a, b)
    // with psi the basis of the cell's shape (a quad's or a triangle's, radiosity/basis.h) and
    // (a, b) the leaf's local coordinates there, affine in position across each cell's
    // triangles on triangle and parallelogram patches.
    Basis basis = Basis::constant;
    std::vector<Vec2> leaf_coordinates;  // per point: its leaf's (a, b)
    // Per cell: its leaf's K x 3 coefficients, coefficient-major (coefficient k's R, G, B,
    // then k + 1's); coefficient 0 is the mean.
    std::vector<double> coefficients;
    std::vector<std::int32_t> leaf_index;  // per cell: its leaf, numbered in canonical order

    std::size_t cell_count() const { return offsets.size() - 1; }
    // The leaves the cells are of: one per cell on the constant basis.
    std::size_t leaf_count() const {
        return leaf_index.empty() ? cell_count() : std::size_t(leaf_index.back()) + 1;
    }
    std::size_t cell_stride() const { return 3 * std::size_t(basis_size(basis)); }
};

// The patches of `h` must have their mesh vertices (h was built from build_patch_set(mesh)): the
// output shares points along mesh edges and at mesh vertices. Patches whose normals differ by
// `crease_degrees` or more are not blended and get separate points. Throws
// std::invalid_argument when the patches have no mesh vertices or they do not match.
// On a higher-order basis the mesh is build_polynomial_mesh(h)'s (radiosity/polynomial_mesh.h),
// whose leaves share no points: crease_degrees has no use there.
ShadedMesh build_shaded_mesh(const Hierarchy& h, double crease_degrees = kCreaseDegrees);
// The same, for a tree nobody needs afterwards: it is released as soon as the conforming
// polygons, the cells' data and the crease flags are taken from it, before the largest arrays
// of the output are built. At 10^6 patches the tree and its patches are 400 MB.
ShadedMesh build_shaded_mesh(std::unique_ptr<Hierarchy> h, double crease_degrees = kCreaseDegrees);
// Fills mesh.cluster_id from each side value's cluster leaf (Solution::cluster_of_side()); leaves
// it empty when that is.
void set_cluster_ids(ShadedMesh& mesh, std::span<const std::int32_t> cluster_of_side);

}  // namespace hmcr
