// SPDX-License-Identifier: Apache-2.0
// The leaves of a solved hierarchy as a conforming polygon mesh with Gouraud vertex radiosity
// (docs/design.md §5): what the VTK export and the image renderer draw.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "common/types.h"
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

    // One cell per leaf, in the canonical leaf order of Hierarchy::for_each_leaf.
    std::vector<Rgb> element_radiosity;  // the leaf's B
    std::vector<int> hierarchy_level;    // the leaf's depth
    std::vector<int> patch_id;
    std::vector<double> element_area;
    // The side of its patch each cell shows: kFront, or kBack for the reversed polygons of a
    // two-sided patch's back, which follow all the fronts.
    std::vector<std::uint8_t> side;
    // The cluster leaf each cell's side belongs to, -1 where the side is in the mesh itself
    // (docs/design.md §2.7); empty without clustering.
    std::vector<std::int32_t> cluster_id;

    std::size_t cell_count() const { return offsets.size() - 1; }
};

// The patches of `h` must have their mesh vertices (h was built from build_patch_set(mesh)): the
// output shares points along mesh edges and at mesh vertices. Patches whose normals differ by
// `crease_degrees` or more are not blended and get separate points. Throws
// std::invalid_argument when the patches have no mesh vertices or they do not match.
ShadedMesh build_shaded_mesh(const Hierarchy& h, double crease_degrees = kCreaseDegrees);
// The same, for a tree nobody needs afterwards: it is released as soon as the conforming
// polygons, the cells' data and the crease flags are taken from it, before the largest arrays
// of the output are built. At 10^6 patches the tree and its patches are 400 MB.
ShadedMesh build_shaded_mesh(std::unique_ptr<Hierarchy> h, double crease_degrees = kCreaseDegrees);
// Fills mesh.cluster_id from each side value's cluster leaf (Solution::cluster_of_side()); leaves
// it empty when that is.
void set_cluster_ids(ShadedMesh& mesh, std::span<const std::int32_t> cluster_of_side);

}  // namespace hmcr
