// SPDX-License-Identifier: Apache-2.0
// The Embree scene built from the patches' mesh vertices (shared between patches) against the
// one built from the patches alone (every patch's corners its own): the same triangles in the
// same order, so every query must give the same bits.
#include "rays/embree_scene.h"

#include <gtest/gtest.h>

#include <vector>

#include "meshes/scene.h"
#include "rays/element_sampler.h"
#include "rays/rng.h"
#include "rays/sampling.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// Rays from uniform points of random patches in cosine directions, and segments between two
// such points: hits, their triangles and barycentric coordinates, and visibility, bit for bit.
void expect_same_queries(const PatchMesh& mesh) {
    const PatchSet set = build_patch_set(mesh);
    const EmbreeScene own(set.patches), shared(set);
    EXPECT_EQ(own.offset(), shared.offset());
    // Each triangle's patch, listed here: both scenes share the triangle-to-patch map.
    std::vector<std::uint32_t> triangle_patch;
    for (std::uint32_t i = 0; i < set.patches.size(); ++i) {
        triangle_patch.insert(triangle_patch.end(), set.patches[i].is_quad() ? 2 : 1, i);
    }
    Rng rng(20261125, 0);
    auto random_point = [&](const Patch*& patch) {
        patch = &set.patches[std::size_t(rng.uniform() * double(set.patches.size()))];
        return patch->point(sample_element(*patch, Domain::root(), rng.uniform(), rng.uniform()));
    };
    int hits = 0, blocked = 0;
    for (int i = 0; i < 20'000; ++i) {
        const Patch* p = nullptr;
        const Vec3 x = random_point(p);
        const Vec3 d = sample_cosine_hemisphere(p->normal, rng.uniform(), rng.uniform());
        const auto a = own.first_hit_triangle(x, d), b = shared.first_hit_triangle(x, d);
        ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
        if (a) {
            ++hits;
            EXPECT_EQ(a->triangle, b->triangle) << "ray " << i;
            EXPECT_EQ(a->u, b->u) << "ray " << i;
            EXPECT_EQ(a->v, b->v) << "ray " << i;
            EXPECT_EQ(a->distance, b->distance) << "ray " << i;
            EXPECT_EQ(own.first_hit(x, d)->patch, triangle_patch.at(a->triangle)) << "ray " << i;
            EXPECT_EQ(shared.first_hit(x, d)->patch, triangle_patch.at(a->triangle)) << "ray " << i;
        }
        const Patch* q = nullptr;
        const Vec3 y = random_point(q);
        const bool seen = own.visible(x, y);
        blocked += !seen;
        EXPECT_EQ(seen, shared.visible(x, y)) << "segment " << i;
    }
    // The queries must have exercised both outcomes, or the comparison says nothing.
    EXPECT_GT(hits, 10'000);
    EXPECT_GT(blocked, 100);
}

TEST(EmbreeScene, SharedVerticesGiveTheSameHitsOnTheCornellBox) {
    expect_same_queries(load_scene("cornell").mesh);
}

TEST(EmbreeScene, SharedVerticesGiveTheSameHitsOnTriangles) {
    expect_same_queries(sphere_around_box());
}

TEST(EmbreeScene, MeshVerticesThatAreNotThePatchesAreRefused) {
    const PatchSet good = build_patch_set(load_scene("cornell").mesh);
    PatchSet set = good;
    set.patches[3].corner_count = 3;  // a quad of the mesh
    EXPECT_THROW(EmbreeScene{set}, std::invalid_argument);
    set = good;
    set.patches.pop_back();
    EXPECT_THROW(EmbreeScene{set}, std::invalid_argument);
    set = good;
    set.vertices.faces[5][1] = set.vertices.vertex_count;
    EXPECT_THROW(EmbreeScene{set}, std::invalid_argument);
    set = good;
    set.vertices = {};  // patches made without a mesh
    EXPECT_THROW(EmbreeScene{set}, std::invalid_argument);
    EXPECT_NO_THROW(EmbreeScene{good});
}

}  // namespace
}  // namespace hmcr::test
