// SPDX-License-Identifier: Apache-2.0
// One input polygon as the engine sees it: corners, plane, material, and the map between its
// parameter space and 3D.
//
// Parameter space: a quad is the bilinear image of [0,1]^2 with corners k at (0,0), (1,0),
// (1,1), (0,1); a triangle is the affine image of {u, v >= 0, u + v <= 1} with corners at
// (0,0), (1,0), (0,1). Both maps are exact for planar patches, so element corners computed in
// parameter space are exact points of the patch.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/types.h"
#include "meshes/connectivity.h"
#include "meshes/patch_mesh.h"

namespace hmcr {

// The z component of the cross product of two plane vectors.
inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

struct Patch {
    std::array<Vec3, 4> corner;  // corner[3] unused on triangles
    Vec3 normal{0, 0, 1};        // unit, right-hand rule of the corner order (the front side)
    double area = 0;
    std::uint32_t material = 0;  // index into PatchSet::materials
    std::uint8_t corner_count = 3;

    bool is_quad() const { return corner_count == 4; }
    // Computes normal, area and the cached map data below from the corners.
    void finalize();

    Vec3 point(const Vec2& uv) const;
    // Parameter coordinates of a point on the patch plane (clamped to the domain).
    Vec2 param(const Vec3& p) const;
    // The parameter point of a hit in the patch's triangle (the second of a quad's two, or
    // the first), at barycentric coordinates (b1, b2) there; `p` is the hit point, which only
    // a quad that is no parallelogram needs (its map is not affine on either triangle).
    Vec2f param_of_hit(bool second_triangle, float b1, float b2, const Vec3& p) const;
    // Area of the region with the given parameter-space corners (3 or 4 of them).
    double region_area(const Vec2* uv, int count) const;
    // |dP/du x dP/dv| at uv: constant on triangles, affine in (u, v) on planar quads.
    double jacobian(const Vec2& uv) const {
        return jacobian_coefficients().dot(Vec3(1, uv.x(), uv.y()));
    }
    // A quad whose bilinear map is affine (rectangles among them): uniform (u, v) is uniform
    // by area.
    bool is_parallelogram() const { return m_parallelogram; }

private:
    // (c0, c1, c2) of J(u, v) = c0 + c1 u + c2 v. Triangles: twice the area. Quads, in the
    // plane: J = cross2(e1 + v g, e2 + u g), affine because cross2(g, g) = 0.
    Vec3 jacobian_coefficients() const {
        if (!is_quad()) return {2 * area, 0, 0};
        if (m_parallelogram) return {cross2(m_e1, m_e2), 0, 0};
        return {cross2(m_e1, m_e2), cross2(m_e1, m_g), cross2(m_g, m_e2)};
    }

    // Cached by finalize(): the map's edge vectors in the patch-plane frame (axis_x, normal x
    // axis_x). The frame's y axis and the Jacobian's coefficients are recomputed where they are
    // needed, from the same expressions, so they are the same bits: a hit's parameters cost one
    // cross product more, a point on a quad that is no parallelogram three 2D ones (48 bytes a
    // patch less: 50 MB at 10^6 patches).
    bool m_parallelogram = false;
    Vec3 m_axis_x{1, 0, 0};
    Vec2 m_e1{1, 0}, m_e2{0, 1}, m_g{0, 0};  // quads: e2 is corner 3 - corner 0
};
// A million patches are 208 MB: the material index, the corner count and the flag share the 8
// bytes after the area, and the 16-byte aligned 2D vectors come last, after 160 bytes, so that
// no padding is needed.
static_assert(sizeof(Patch) == 208);

// A patch's two sides (docs/design.md §1.3): the front, which its normal points out of, and the
// back, which only a two-sided patch has (its own material, radiosity and elements).
inline constexpr std::uint8_t kFront = 0, kBack = 1;

// The unit normal out of a side: the patch's for the front, reversed for the back.
inline Vec3 side_normal(const Patch& p, std::uint8_t side) {
    return side == kFront ? p.normal : Vec3(-p.normal);
}

struct PatchMaterial {
    Rgb reflectance = Rgb::Zero();  // diffuse: the radiosity engine's rho
    Rgb emission = Rgb::Zero();     // emitted radiosity E, W/m^2
    // Specular reflectance and its lobe's roughness (0: a mirror), which only the path tracer
    // reflects: the radiosity engine absorbs it (docs/design.md §1.2).
    Rgb specular = Rgb::Zero();
    double roughness = 0;
};

// The patches of a mesh in face order, their materials, the mesh vertex of each corner, and the
// scene constants the oracles need.
struct PatchSet {
    std::vector<Patch> patches;
    // Which mesh vertex each corner is (empty for patches made without a mesh): the mesh
    // connectivity that the Embree scene and the output need, so nothing needs the mesh itself.
    FaceVertices vertices;
    std::vector<PatchMaterial> materials{PatchMaterial{}};  // patches name them by index
    // The material of each patch's back side, or kOneSided; empty when no patch has a back.
    std::vector<std::uint32_t> back_materials;
    double total_area = 0;            // A_T, of the sides: a two-sided patch's area counts twice
    double max_emitted_power = 0;     // Phi_max: largest A_i * max_c E_i,c of any side
    Rgb emitted_power = Rgb::Zero();  // sum of A_i * E_i over the sides

    const Rgb& reflectance(const Patch& p) const { return materials[p.material].reflectance; }
    const Rgb& emission(const Patch& p) const { return materials[p.material].emission; }

    bool two_sided(std::size_t patch) const {
        return !back_materials.empty() && back_materials[patch] != kOneSided;
    }
    // The material of a side; the back's only if the patch is two-sided.
    const PatchMaterial& material(std::size_t patch, std::uint8_t side) const {
        return materials[side == kFront ? patches[patch].material : back_materials[patch]];
    }
};

PatchSet build_patch_set(const PatchMesh& mesh);

}  // namespace hmcr
