// SPDX-License-Identifier: Apache-2.0
// The Embree scene built from the patches' mesh vertices (shared between patches) against the
// one built from the patches alone (every patch's corners its own): the same triangles in the
// same order, so every query must give the same bits. And a batch's packets against single rays.
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

// Each Embree triangle's patch and whether it is a quad's second, listed here rather than taken
// from the scene's own map (a quad is two triangles, in patch order).
struct TriangleOf {
    std::vector<std::uint32_t> patch;
    std::vector<bool> second;
};
TriangleOf triangles_of(const PatchSet& set) {
    TriangleOf t;
    for (std::uint32_t i = 0; i < set.patches.size(); ++i) {
        for (int k = 0; k < (set.patches[i].is_quad() ? 2 : 1); ++k) {
            t.patch.push_back(i);
            t.second.push_back(k == 1);
        }
    }
    return t;
}

// Rays from uniform points of random patches in cosine directions, and segments between two
// such points: hits, their triangles and barycentric coordinates, and visibility, bit for bit.
void expect_same_queries(const PatchMesh& mesh) {
    const PatchSet set = build_patch_set(mesh);
    const EmbreeScene own(set.patches), shared(set);
    EXPECT_EQ(own.offset(), shared.offset());
    const std::vector<std::uint32_t> triangle_patch = triangles_of(set).patch;
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

// The packets of first_hits() against one single-ray query a ray: the same patch, triangle,
// distance and barycentric coordinates, bit for bit, for ranges that start anywhere and end in a
// partial packet.
void expect_packets_give_single_ray_hits(const PatchMesh& mesh) {
    const PatchSet set = build_patch_set(mesh);
    const EmbreeScene scene(set);
    const TriangleOf triangle = triangles_of(set);
    constexpr std::size_t n = 20'003;
    GeneratedRays rays;
    rays.resize(n);
    Rng rng(20261208, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const Patch& p = set.patches[std::size_t(rng.uniform() * double(set.patches.size()))];
        const Vec3 x = p.point(sample_element(p, Domain::root(), rng.uniform(), rng.uniform()));
        const Vec3 d = sample_cosine_hemisphere(p.normal, rng.uniform(), rng.uniform());
        for (int c = 0; c < 3; ++c) {
            rays.origin[c][k] = float(x[c]);
            rays.direction[c][k] = float(d[c]);
        }
    }
    int hits = 0;
    for (const std::size_t begin : {std::size_t(0), std::size_t(5)}) {
        std::vector<BatchHit> packed(n);
        scene.first_hits(rays, begin, n, packed);
        for (std::size_t k = begin; k < n; ++k) {
            const Vec3 x(rays.origin[0][k], rays.origin[1][k], rays.origin[2][k]);
            const Vec3 d(rays.direction[0][k], rays.direction[1][k], rays.direction[2][k]);
            const auto one = scene.first_hit_triangle(x, d);
            const BatchHit& h = packed[k];
            ASSERT_EQ(one.has_value(), h.patch != BatchHit::kNoHit) << "ray " << k;
            if (!one) continue;
            ++hits;
            EXPECT_EQ(h.patch, triangle.patch.at(one->triangle)) << "ray " << k;
            EXPECT_EQ(bool(h.second_triangle), triangle.second.at(one->triangle)) << "ray " << k;
            EXPECT_EQ(double(h.distance), one->distance) << "ray " << k;
            EXPECT_EQ(double(h.b1), one->u) << "ray " << k;
            EXPECT_EQ(double(h.b2), one->v) << "ray " << k;
        }
    }
    EXPECT_GT(hits, 20'000);  // both ranges, most rays landing
}

TEST(EmbreeScene, PacketsGiveTheSingleRayHitsOnTheCornellBox) {
    expect_packets_give_single_ray_hits(load_scene("cornell").mesh);
}

TEST(EmbreeScene, PacketsGiveTheSingleRayHitsOnTriangles) {
    expect_packets_give_single_ray_hits(sphere_around_box());
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
