// SPDX-License-Identifier: Apache-2.0
// Conforming polygons for the leaves of a hierarchy: every leaf becomes a polygon that also
// lists the corners of finer neighbouring leaves lying on its edges, so the output has no
// T-junctions (docs/design.md §5), within a patch and across mesh edges shared by two patches.
//
// Method: leaf corners are dyadic in parameter space (depth <= 24), so they sit exactly on an
// integer grid of 2^24 steps per unit. A vertex is identified by its mesh vertex (patch
// corners), by its mesh edge and integer position along that edge from the edge's lower vertex
// index (patch boundary points), or by its patch and grid coordinates (interior points). Both
// faces of a mesh edge parameterise it linearly, so a grid position along the edge is the same
// point seen from either side. Every leaf edge lies on a supporting line (u = c, v = c, or on
// triangles u + v = c; boundary lines are the mesh edges); collecting all leaf corners per line
// and inserting those strictly inside each leaf edge makes the polygons conform.
//
// Out of scope: T-junctions already present in the input (a mesh vertex of one patch in the
// middle of another patch's edge without a shared mesh edge) stay T-junctions. The Cornell box
// has them where the 3x3 ceiling grid meets the one-quad walls; those are 90-degree creases, so
// the shading is unaffected there and only hairline cracks can show.
#pragma once

#include <cstdint>
#include <vector>

#include "common/types.h"
#include "meshes/connectivity.h"
#include "radiosity/hierarchy.h"

namespace hmcr {

// What a vertex is attached to in the patch mesh; id is a mesh vertex, mesh edge or patch index.
enum class VertexKind : std::uint8_t { mesh_vertex, mesh_edge, patch_interior };

struct LatticeVertex {
    VertexKind kind;
    std::uint32_t id;
    Vec3 position;
};

struct ConformingPolygons {
    std::vector<LatticeVertex> vertices;          // in order of first use
    std::vector<std::int64_t> offsets{0};         // one polygon per leaf of the side, in order
    std::vector<std::uint32_t> polygon_vertices;  // indices into vertices, counter-clockwise
};

// The polygons of one side's leaves (docs/design.md §5.3): a back side's polygons are
// reversed, so that they face out of the back. The mesh is the patches' own:
// PatchSet::vertices, and `edges` = face_edges() of them. Throws std::invalid_argument when the
// patches have no mesh vertices or they do not match.
ConformingPolygons build_conforming_polygons(const Hierarchy& h, const FaceEdges& edges,
                                             std::uint8_t side = kFront);

}  // namespace hmcr
