// SPDX-License-Identifier: Apache-2.0
// Embree behind a small RAII facade: the rest of hmcr asks for first hits and visibility and
// never touches RTC types. Quads are traced as two triangles; hits report the patch index.
// A scene can also be built from a plain triangle soup (the renderer's Gouraud mesh): there a
// "patch" is the triangle index, and first_hit_triangle() adds the hit's barycentric position.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "rays/patch.h"
#include "rays/ray_generator.h"
#include "rays/triangle_patches.h"

namespace hmcr {

struct Hit {
    std::uint32_t patch = 0;
    double distance = 0;  // along the (unit) direction
};

// A hit on a triangle of the soup: the hit point is (1 - u - v) p0 + u p1 + v p2 for the
// triangle's vertices p0, p1, p2 in the order given (Embree's convention).
struct TriangleHit {
    std::uint32_t triangle = 0;
    double u = 0, v = 0;
    double distance = 0;  // along the (unit) direction
    // The triangle's geometric normal, not normalised: (p1 - p0) x (p2 - p0), out of the side
    // from which its corners run counter-clockwise.
    Vec3 normal{0, 0, 0};
};

// The first hit of a batch ray: its patch (kNoHit when the ray leaves the scene), which of a
// quad's two triangles it hit (0 or 1), the distance along the ray and Embree's barycentric
// coordinates in that triangle (the hit is (1 - b1 - b2) p0 + b1 p1 + b2 p2).
struct BatchHit {
    static constexpr std::uint32_t kNoHit = ~std::uint32_t(0);
    std::uint32_t patch = kNoHit;
    std::uint32_t second_triangle = 0;
    float distance = 0, b1 = 0, b2 = 0;
};

class EmbreeScene {
public:
    // Each patch's corners are vertices of their own.
    explicit EmbreeScene(const std::vector<Patch>& patches);
    // The same scene, the same hits, with the mesh's vertices shared by the patches that meet
    // there: at 10^6 patches 13 MB of vertices instead of 50. The patches must have their mesh
    // vertices (throws std::invalid_argument otherwise).
    explicit EmbreeScene(const PatchSet& set);
    // A triangle soup: indices into `vertices`. Degenerate triangles are allowed (and never hit).
    // Built robust (Embree's RTC_SCENE_FLAG_ROBUST: watertight edge tests and conservative
    // traversal): an image's rays come on a regular grid, and with Embree's fast tests a ray
    // through the edge two triangles share can meet neither: a black pixel in a closed room.
    // Throws std::invalid_argument on an index out of range.
    EmbreeScene(const std::vector<Vec3>& vertices,
                const std::vector<std::array<unsigned, 3>>& triangles);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // First surface hit along a unit direction, ignoring hits closer than the self-hit offset.
    std::optional<Hit> first_hit(const Vec3& origin, const Vec3& direction) const;
    // first_hit() with the triangle and its barycentric coordinates (for a patch scene the
    // triangle index counts the two triangles of each quad).
    std::optional<TriangleHit> first_hit_triangle(const Vec3& origin, const Vec3& direction) const;
    // first_hit() of rays [begin, end) of a batch into hits[begin, end), for a patch scene, in
    // 16-wide packets from `begin` (kPacketRays; docs/design.md §3.3 says why). Embree's order of
    // traversal follows a packet's rays, so a tie between two triangles could go either way by
    // a ray's packet mates: ranges that start at multiples of kPacketRays of one numbering make
    // the same packets, and the same hits, however the numbering is split.
    void first_hits(const GeneratedRays& rays, std::size_t begin, std::size_t end,
                    std::span<BatchHit> hits) const;
    // Whether the open segment between two surface points is unoccluded.
    bool visible(const Vec3& p, const Vec3& q) const;
    // visible() for many segments at once, 16 per coherent packet (the segments of one element
    // pair are coherent: docs/design.md §4 line sampling).
    void visible_many(std::span<const Vec3> p, std::span<const Vec3> q, std::span<bool> out) const;

    double offset() const { return m_offset; }  // self-hit offset, metres

    static constexpr std::size_t kPacketRays = 16;  // rays in one first_hits() query

    struct Impl;  // opaque: keeps RTC types out of this header

private:
    // The BVH of `triangle_count` triangles over `vertex_count` vertices, which fill(vertices,
    // triangles) writes straight into Embree's buffers: 3 floats, 3 vertex indices each.
    void build(std::size_t vertex_count, std::size_t triangle_count, const Vec3& lo, const Vec3& hi,
               const std::function<void(float*, unsigned*)>& fill, bool robust = false);

    // build() for patches: their bounds, and the triangles add_patch_triangles() writes.
    void build_patches(const std::vector<Patch>& patches, std::size_t vertex_count,
                       const std::function<void(float*, unsigned*)>& fill);
    // The next patch, with corners at vertices v: (v0, v1, v2), and (v0, v2, v3) for a quad.
    // Patches are added in order: a triangle's patch follows from its number.
    void add_patch_triangles(const unsigned* v, bool quad, unsigned*& index);

    std::unique_ptr<Impl> m_impl;
    TrianglePatches m_triangle_patch;
    double m_offset = 0;
};

// Sets flush-to-zero and denormals-are-zero in the calling thread, as Embree recommends for
// every thread that traces.
void set_tracing_float_mode();

}  // namespace hmcr
