// SPDX-License-Identifier: Apache-2.0
#include "radiosity/shaded_mesh.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "tests/support/shaded_scenes.h"

namespace hmcr::test {
namespace {

constexpr double kEps = 1e-12;  // exact arithmetic up to rounding of unit-sized scenes

Vec3 at_param(const MeshHierarchy& s, int patch, double u, double v) {
    return s.h->patch_set().patches[patch].point(Vec2(u, v));
}

// Cells follow the canonical leaf order with their data; polygons are counter-clockwise around
// the patch normal with the leaf's area; the patches are covered exactly; no T-junctions.
void expect_well_formed(const MeshHierarchy& s, const ShadedMesh& m) {
    ASSERT_EQ(m.cell_count(), s.h->leaf_count());
    ASSERT_EQ(m.point_radiosity.size(), m.points.size());
    std::size_t c = 0;
    std::vector<double> patch_area(s.h->patch_count(), 0.0);
    s.h->for_each_leaf([&](const Element& e) {
        EXPECT_EQ(m.patch_id[c], int(e.id.patch));
        EXPECT_EQ(m.hierarchy_level[c], int(e.id.depth));
        EXPECT_TRUE((m.element_radiosity[c] == e.radiosity).all());
        EXPECT_DOUBLE_EQ(m.element_area[c], e.area);
        const Vec3 a = polygon_area(m, std::int64_t(c));
        EXPECT_NEAR(a.dot(s.h->patch(e).normal), e.area, kEps) << "cell " << c;
        patch_area[e.id.patch] += a.norm();
        ++c;
    });
    for (std::size_t p = 0; p < s.h->patch_count(); ++p) {
        EXPECT_NEAR(patch_area[p], s.h->patch_set().patches[p].area, kEps) << "patch " << p;
    }
    EXPECT_TRUE(conforming(m));
}

std::size_t distinct_positions(const ShadedMesh& m) {
    std::set<std::tuple<double, double, double>> seen;
    for (const Vec3& p : m.points) seen.insert({p.x(), p.y(), p.z()});
    return seen.size();
}

// Every leaf of the scene gets B = value.
void fill(MeshHierarchy& s, int patch, double value) {
    s.for_leaves(patch, [&](Element& e) { e.radiosity = Rgb::Constant(value); });
}

Rgb value_at(const ShadedMesh& m, const Vec3& x) {
    const auto idx = points_at(m, x);
    EXPECT_EQ(idx.size(), 1u) << "at " << x.transpose();
    return idx.empty() ? Rgb::Constant(-1) : m.point_radiosity[idx[0]];
}

TEST(ShadedMesh, QuadLeavesBecomeConformingCells) {
    MeshHierarchy s(make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}));
    s.at(0, {0, 3, 1});
    s.at(0, {3, 2});
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    EXPECT_EQ(m.points.size(), distinct_positions(m));  // one patch: one point per position
}

TEST(ShadedMesh, VertexValueIsAreaWeightedAverageOfLeavesAround) {
    MeshHierarchy s(make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}));
    s.at(0, {0, 0});
    // Children 1..3 of the root (area 1/4) and the four grandchildren below child 0 (1/16).
    for (int k = 1; k < 4; ++k) s.at(0, {k}).radiosity = Rgb::Constant(k);
    for (int k = 0; k < 4; ++k) s.at(0, {0, k}).radiosity = Rgb(10 + k, 20 + k, 30 + k);
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    // (1/2, 1/2): children 1, 2, 3 and grandchild 0/3.
    const Rgb centre = (0.25 * Rgb::Constant(1 + 2 + 3) + 0.0625 * Rgb(13, 23, 33)) / 0.8125;
    EXPECT_TRUE(value_at(m, at_param(s, 0, 0.5, 0.5)).isApprox(centre, kEps));
    // (1/2, 1/4) lies inside child 1's edge: child 1 and grandchildren 0/1, 0/3.
    const Rgb t_junction = (0.25 * Rgb::Constant(1) + 0.0625 * Rgb(24, 44, 64)) / 0.375;
    EXPECT_TRUE(value_at(m, at_param(s, 0, 0.5, 0.25)).isApprox(t_junction, kEps));
    EXPECT_TRUE(value_at(m, at_param(s, 0, 0, 0)).isApprox(Rgb(10, 20, 30), kEps));
}

TEST(ShadedMesh, LinearFieldIsReproducedAtInteriorVertices) {
    MeshHierarchy s(make_mesh({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}));
    for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 4; ++b) s.at(0, {a, b});
    }
    const Rgb a(1, 2, 3), b(0.5, -0.25, 2);
    s.for_leaves(0, [&](Element& e) { e.radiosity = a + b * e.centre.x(); });
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    ASSERT_EQ(m.points.size(), 25u);
    for (int i = 1; i < 4; ++i) {
        for (int j = 1; j < 4; ++j) {
            const Vec3 x = at_param(s, 0, i / 4.0, j / 4.0);
            EXPECT_TRUE(value_at(m, x).isApprox(a + b * x.x(), kEps)) << x.transpose();
        }
    }
}

// Patch 0 split once (B = 1, leaves of area 1/4), patch 1 left whole (B = 3, area 1).
MeshHierarchy split_pair(bool coplanar) {
    MeshHierarchy s(two_quads(coplanar));
    s.at(0, {0});
    fill(s, 0, 1);
    fill(s, 1, 3);
    return s;
}

TEST(ShadedMesh, CoplanarPatchesShareConformingPoints) {
    MeshHierarchy s = split_pair(true);
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    EXPECT_EQ(m.points.size(), distinct_positions(m));
    EXPECT_EQ(m.offsets[5] - m.offsets[4], 5);  // patch 1 carries the midpoint of the edge
    EXPECT_TRUE(value_at(m, {1, 0.5, 0}).isApprox(Rgb::Constant(3.5 / 1.5), kEps));
    EXPECT_TRUE(value_at(m, {1, 0, 0}).isApprox(Rgb::Constant(3.25 / 1.25), kEps));
}

// A light in a ceiling: coplanar, but B jumps with E, so the edge is not blended.
TEST(ShadedMesh, CoplanarPatchesOfDifferentMaterialsAreNotBlended) {
    MeshHierarchy s = split_pair(true);
    set_face_material(s.mesh, PatchMesh::FaceHandle(1), {{0.5, 0.5, 0.5}, {2, 2, 2}});
    s.h = std::make_unique<Hierarchy>(build_patch_set(s.mesh), HierarchyLimits{0, 24});
    s.at(0, {0});
    fill(s, 0, 1);
    fill(s, 1, 3);
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    for (const Vec3& x : {Vec3(1, 0.5, 0), Vec3(1, 0, 0)}) {
        const auto idx = points_at(m, x);
        ASSERT_EQ(idx.size(), 2u) << x.transpose();
        std::multiset<double> values = {m.point_radiosity[idx[0]][0], m.point_radiosity[idx[1]][0]};
        EXPECT_EQ(values, (std::multiset<double>{1.0, 3.0}));
    }
}

TEST(ShadedMesh, CoplanarPatchesWithDeepSubdivisionConform) {
    MeshHierarchy s(two_quads(true));
    s.at(0, {1, 3, 1, 3, 1});
    s.at(0, {3, 1, 1});
    s.at(1, {0, 2, 0});
    s.at(1, {2, 0, 2});
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    EXPECT_EQ(m.points.size(), distinct_positions(m));
}

TEST(ShadedMesh, CreaseSplitsPointsBetweenPerpendicularPatches) {
    MeshHierarchy s = split_pair(false);
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    for (const Vec3& x : {Vec3(1, 0.5, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}) {
        const auto idx = points_at(m, x);
        ASSERT_EQ(idx.size(), 2u) << x.transpose();
        std::multiset<double> values = {m.point_radiosity[idx[0]][0], m.point_radiosity[idx[1]][0]};
        EXPECT_EQ(values, (std::multiset<double>{1.0, 3.0}));
    }
    // Each cell uses the point of its own patch.
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        for (auto i = m.offsets[c]; i < m.offsets[c + 1]; ++i) {
            EXPECT_EQ(m.point_radiosity[m.connectivity[i]][0], m.patch_id[c] == 0 ? 1.0 : 3.0);
        }
    }
}

// `hmcr solve` hands its tree over, to be released half-way: the mesh must be the same.
TEST(ShadedMesh, ATreeHandedOverGivesTheSameMesh) {
    MeshHierarchy s = split_pair(false);
    const ShadedMesh kept = s.shade();
    const ShadedMesh handed = build_shaded_mesh(std::move(s.h));
    EXPECT_EQ(handed.points, kept.points);
    EXPECT_EQ(handed.offsets, kept.offsets);
    EXPECT_EQ(handed.connectivity, kept.connectivity);
    EXPECT_EQ(handed.hierarchy_level, kept.hierarchy_level);
    EXPECT_EQ(handed.patch_id, kept.patch_id);
    EXPECT_EQ(handed.element_area, kept.element_area);
    ASSERT_EQ(handed.point_radiosity.size(), kept.point_radiosity.size());
    for (std::size_t i = 0; i < kept.point_radiosity.size(); ++i) {
        EXPECT_TRUE((handed.point_radiosity[i] == kept.point_radiosity[i]).all()) << i;
    }
    ASSERT_EQ(handed.element_radiosity.size(), kept.element_radiosity.size());
    for (std::size_t c = 0; c < kept.element_radiosity.size(); ++c) {
        EXPECT_TRUE((handed.element_radiosity[c] == kept.element_radiosity[c]).all()) << c;
    }
}

TEST(ShadedMesh, WideCreaseAngleBlendsPerpendicularPatches) {
    MeshHierarchy s = split_pair(false);
    const ShadedMesh m = s.shade(100);
    expect_well_formed(s, m);
    EXPECT_EQ(m.points.size(), distinct_positions(m));
    EXPECT_TRUE(value_at(m, {1, 0.5, 0}).isApprox(Rgb::Constant(3.5 / 1.5), kEps));
}

TEST(ShadedMesh, TrianglesWithInvertedChildrenConform) {
    MeshHierarchy s(two_triangles());
    s.at(0, {3, 3, 0});  // middle child, its middle child (upright again), a corner below
    s.at(0, {3, 1});
    s.at(0, {1, 2, 3});
    s.at(1, {0, 1});
    s.at(1, {1});
    s.for_leaves(0, [&](Element& e) { e.radiosity = Rgb::Constant(e.centre.x()); });
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    EXPECT_EQ(m.points.size(), distinct_positions(m));
}

TEST(ShadedMesh, TriangleVertexValueOnHypotenuse) {
    MeshHierarchy s(make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
    s.at(0, {3, 0});
    for (int k = 0; k < 3; ++k) s.at(0, {k}).radiosity = Rgb::Constant(k);
    for (int k = 0; k < 4; ++k) s.at(0, {3, k}).radiosity = Rgb::Constant(10 * (k + 1));
    const ShadedMesh m = s.shade();
    expect_well_formed(s, m);
    // (1/4, 1/4) is the middle of corner child 0's hypotenuse: child 0 (area 1/8) and the
    // middle child's children 1 and 2 (1/32 each) and 3 (1/32, inverted below them).
    const Rgb expected = Rgb::Constant((0.125 * 0 + (20 + 30 + 40) / 32.0) / (0.125 + 3 / 32.0));
    EXPECT_TRUE(value_at(m, at_param(s, 0, 0.25, 0.25)).isApprox(expected, kEps));
}

TEST(ShadedMesh, RejectsPatchesWithoutTheirMeshVertices) {
    const PatchMesh mesh = two_quads(true);
    PatchSet set = build_patch_set(mesh);
    set.vertices = face_vertices(make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
    EXPECT_THROW(build_shaded_mesh(Hierarchy(set, {})), std::invalid_argument);
    set.vertices = face_vertices(
        make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 3, 2}}));
    EXPECT_THROW(build_shaded_mesh(Hierarchy(set, {})), std::invalid_argument);
    set.vertices = {};
    EXPECT_THROW(build_shaded_mesh(Hierarchy(set, {})), std::invalid_argument);
    set.vertices = face_vertices(mesh);
    EXPECT_NO_THROW(build_shaded_mesh(Hierarchy(set, {})));
}

}  // namespace
}  // namespace hmcr::test
