// SPDX-License-Identifier: Apache-2.0
// The mesh's connectivity as plain arrays against the OpenMesh mesh it comes from.
#include "meshes/connectivity.h"

#include <gtest/gtest.h>

#include <vector>

#include "meshes/scene.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// Every face's corners and sides are the mesh's vertices and edges, with the mesh's own numbers:
// OpenMesh numbers edges in order of first appearance too.
void expect_same_as_openmesh(const PatchMesh& mesh) {
    const FaceVertices v = face_vertices(mesh);
    const FaceEdges e = face_edges(v);
    ASSERT_EQ(v.faces.size(), mesh.n_faces());
    ASSERT_EQ(e.faces.size(), mesh.n_faces());
    EXPECT_EQ(v.vertex_count, mesh.n_vertices());
    EXPECT_EQ(e.edge_count, mesh.n_edges());
    for (auto f : mesh.faces()) {
        const int n = v.corner_count(f.idx());
        ASSERT_EQ(n, int(mesh.valence(f)));
        int k = 0;
        for (auto fv : mesh.fv_range(f)) EXPECT_EQ(v.faces[f.idx()][k++], unsigned(fv.idx()));
        for (k = 0; k < n; ++k) {
            const auto h =
                mesh.find_halfedge(PatchMesh::VertexHandle(int(v.faces[f.idx()][k])),
                                   PatchMesh::VertexHandle(int(v.faces[f.idx()][(k + 1) % n])));
            ASSERT_TRUE(h.is_valid());
            EXPECT_EQ(e.faces[f.idx()][k], unsigned(mesh.edge_handle(h).idx()))
                << "face " << f.idx() << " side " << k;
        }
        if (n == 3) {
            EXPECT_EQ(v.faces[f.idx()][3], kNoCorner);
            EXPECT_EQ(e.faces[f.idx()][3], kNoCorner);
        }
    }
}

TEST(Connectivity, QuadsWithTJunctionsAreTheMeshsOwn) {
    expect_same_as_openmesh(load_scene("cornell").mesh);
}

TEST(Connectivity, TrianglesAndQuadsAreTheMeshsOwn) {
    expect_same_as_openmesh(sphere_around_box());
}

// An edge shared by two faces has one number, the one of its first appearance.
TEST(Connectivity, TwoTrianglesShareOneEdge) {
    FaceVertices v;
    v.vertex_count = 4;
    v.faces = {{0, 1, 2, kNoCorner}, {2, 1, 3, kNoCorner}};
    const FaceEdges e = face_edges(v);
    EXPECT_EQ(e.edge_count, 5u);
    EXPECT_EQ(e.faces[0][0], 0u);  // 0-1
    EXPECT_EQ(e.faces[0][1], 1u);  // 1-2
    EXPECT_EQ(e.faces[0][2], 2u);  // 2-0
    EXPECT_EQ(e.faces[1][0], 1u);  // 2-1: the same edge as 1-2
    EXPECT_EQ(e.faces[1][1], 3u);  // 1-3
    EXPECT_EQ(e.faces[1][2], 4u);  // 3-2
}

}  // namespace
}  // namespace hmcr::test
