// SPDX-License-Identifier: Apache-2.0
// The element quadtree (docs/design.md §2): areas, point location, identities, limits, push-pull.
#include "radiosity/hierarchy.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "rays/rng.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// A skewed planar quad (not a parallelogram) and a triangle, side by side.
std::vector<TestPolygon> quad_and_triangle() {
    TestPolygon q{
        {{0, 0, 0}, {2, 0, 0}, {1.6, 1.2, 0}, {0.2, 0.9, 0}}, Rgb::Constant(0.5), Rgb::Zero()};
    TestPolygon t{{{3, 0, 0}, {5, 0.5, 0}, {3.5, 2, 0}}, Rgb::Constant(0.5), Rgb::Constant(1)};
    return {q, t};
}

Hierarchy make_hierarchy(HierarchyLimits limits = {}) {
    return Hierarchy(build_patch_set(make_patch_mesh(quad_and_triangle())), limits);
}

void subdivide_everywhere(Hierarchy& h, Element& e, int depth) {
    if (depth == 0) return;
    Element* c = h.subdivide(e);
    for (int k = 0; k < 4; ++k) subdivide_everywhere(h, c[k], depth - 1);
}

// Each patch reads its material from the mesh's table by the face's index; a face naming a
// material the table lacks, or a mesh without the table, is refused instead of read past.
TEST(PatchSet, MaterialsComeFromTheMeshTableByIndex) {
    PatchMesh mesh = make_patch_mesh(quad_and_triangle());
    const PatchSet set = build_patch_set(mesh);
    ASSERT_EQ(set.patches.size(), 2u);
    EXPECT_TRUE((set.reflectance(set.patches[0]) == Rgb::Constant(0.5)).all());
    EXPECT_TRUE((set.emission(set.patches[0]) == Rgb::Zero()).all());
    EXPECT_TRUE((set.emission(set.patches[1]) == Rgb::Constant(1)).all());
    EXPECT_DOUBLE_EQ(set.max_emitted_power, set.patches[1].area);
    material_prop(mesh)[OpenMesh::FaceHandle(1)] = 7;
    EXPECT_THROW(build_patch_set(mesh), std::invalid_argument);
    PatchMesh bare;
    bare.add_face(bare.add_vertex({0, 0, 0}), bare.add_vertex({1, 0, 0}),
                  bare.add_vertex({0, 1, 0}));
    EXPECT_THROW(build_patch_set(bare), std::invalid_argument);
}

TEST(Hierarchy, ChildAreasSumToTheParent) {
    Hierarchy h = make_hierarchy();
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        subdivide_everywhere(h, h.root(p), 3);
        double leaves = 0;
        Hierarchy::visit_leaves(h.root(p), [&](const Element& e) { leaves += e.area; });
        EXPECT_NEAR(leaves, h.root(p).area, 1e-12 * h.root(p).area);
        const Element* c = h.root(p).children();
        EXPECT_NEAR(c[0].area + c[1].area + c[2].area + c[3].area, h.root(p).area, 1e-12);
    }
    // On a triangle all four children have a quarter of the area, the middle one included.
    const Element* t = h.root(1).children();
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(t[k].area, h.root(1).area / 4, 1e-12);
}

TEST(Hierarchy, PointLocationFindsTheLeafWhoseRegionContainsThePoint) {
    Hierarchy h = make_hierarchy();
    for (std::size_t p = 0; p < h.patch_count(); ++p) subdivide_everywhere(h, h.root(p), 4);
    Rng rng(3, 0);
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        const Patch& patch = h.patch_set().patches[p];
        for (int k = 0; k < 2000; ++k) {
            Vec2 uv(rng.uniform(), rng.uniform());
            if (!patch.is_quad() && uv.sum() > 1) uv = Vec2(1, 1) - uv;
            // Round trip through 3D, as for a ray hit.
            const Vec2 back = patch.param(patch.point(uv));
            ASSERT_NEAR((back - uv).norm(), 0, 1e-9);
            const Element& leaf = h.locate(h.root(p), back);
            EXPECT_EQ(leaf.id.depth, 4);
            const Domain& d = leaf.domain;
            const double a = (uv.x() - d.u0) / d.s, b = (uv.y() - d.v0) / d.s;
            const double tol = 1e-9;
            EXPECT_TRUE(a >= -tol && b >= -tol &&
                        (patch.is_quad() ? a <= 1 + tol && b <= 1 + tol : a + b <= 1 + tol))
                << "uv " << uv.transpose() << " not in leaf " << leaf.id.to_string();
        }
    }
}

TEST(Hierarchy, IdentitiesAreTheChildPathsAndUnique) {
    Hierarchy h = make_hierarchy();
    subdivide_everywhere(h, h.root(0), 3);
    std::set<ElementId> ids;
    h.for_each_leaf([&](const Element& e) { EXPECT_TRUE(ids.insert(e.id).second); });
    EXPECT_EQ(ids.size(), 64u + 1u);
    const Element& e = h.root(0).children()[2].children()[1].children()[3];
    EXPECT_EQ(e.id.to_string(), "0/213");
    EXPECT_EQ(h.element_count(), 2u + 4 + 16 + 64);
    EXPECT_EQ(h.leaf_count(), 65u);
}

TEST(Hierarchy, UniformSubdivisionSplitsExactlyTheElementsAboveTheArea) {
    Hierarchy h = make_hierarchy();
    const double max_area = 0.01;
    h.subdivide_uniformly(max_area);
    // Every split element is above the area, every leaf at or below it.
    auto check = [&](auto&& self, const Element& e) -> void {
        if (e.is_leaf()) {
            EXPECT_LE(e.area, max_area);
            return;
        }
        EXPECT_GT(e.area, max_area);
        for (int k = 0; k < 4; ++k) self(self, e.children()[k]);
    };
    for (std::uint32_t p = 0; p < h.patch_count(); ++p) check(check, h.root(p));
    EXPECT_GT(h.leaf_count(), 100u);
}

// docs/design.md §2: a 1M-element hierarchy must fit well under 1 GiB.
TEST(Hierarchy, AMillionElementsFitInAFifthOfAGibibyte) {
    EXPECT_LE(sizeof(Element) * 1'000'000, std::size_t(200) << 20) << sizeof(Element);
}

TEST(Hierarchy, LimitsStopSubdivision) {
    Hierarchy by_depth = make_hierarchy({0, 2});
    EXPECT_TRUE(by_depth.can_subdivide(by_depth.root(0)));
    const Element& d2 = by_depth.subdivide(by_depth.subdivide(by_depth.root(0))[0])[0];
    EXPECT_FALSE(by_depth.can_subdivide(d2));

    Hierarchy by_area = make_hierarchy({0.05, 24});  // 5% of A_T
    const double limit = 0.05 * by_area.patch_set().total_area;
    subdivide_everywhere(by_area, by_area.root(0), 3);
    by_area.for_each_leaf([&](const Element& e) {
        EXPECT_EQ(by_area.can_subdivide(e), e.area > limit) << e.id.to_string();
    });
}

TEST(Hierarchy, NewChildrenInheritRadiosityAndPushPullConservesPower) {
    Hierarchy h = make_hierarchy();
    const Rgb emitted = h.root(1).area * h.root(1).radiosity;
    subdivide_everywhere(h, h.root(1), 2);
    h.for_each_leaf([&](const Element& e) {
        if (e.id.patch == 1) {
            EXPECT_TRUE((e.radiosity == Rgb::Constant(1)).all());
        }
    });
    // Receive power at several levels, then push-pull: no power is created or lost.
    Element& root = h.root(0);
    subdivide_everywhere(h, root, 3);
    const Rgb p0(1.0, 2.0, 3.0), p1(0.5, 0.25, 0.125);
    const PowerQuantum quantum{Rgb(0x1p-40, 0x1p-41, 0x1p-42)};  // each p a whole count of them
    add(root.received, quantum.count(p0, 0.5));
    Element& mid = root.children()[3].children()[1];
    add(mid.received, quantum.count(p1, 0.5));
    const Rgb before = h.unshot_power();
    h.push_pull(quantum);
    const Rgb after = h.unshot_power();
    // Unshot power was emitted on patch 1 only; now it is what patch 0 received.
    EXPECT_TRUE(before.isApprox(emitted, 1e-12));
    EXPECT_TRUE(after.isApprox(p0 + p1, 1e-12)) << after.transpose();
    EXPECT_NEAR(mid.unshot[0], (p0[0] / root.area) + p1[0] / mid.area, 1e-12);
}

}  // namespace
}  // namespace hmcr::test
