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

#include "meshes/patch_mesh.h"
#include "common/types.h"

namespace hmcr {

struct Patch {
    std::array<Vec3, 4> corner;  // corner[3] unused on triangles
    Vec3 normal{0, 0, 1};        // unit, right-hand rule of the corner order (the front side)
    double area = 0;
    int corner_count = 3;
    std::uint32_t material = 0;  // index into PatchSet::materials

    bool is_quad() const { return corner_count == 4; }
    // Computes normal, area and the cached map data below from the corners.
    void finalize();

    Vec3 point(const Vec2& uv) const;
    // Parameter coordinates of a point on the patch plane (clamped to the domain).
    Vec2 param(const Vec3& p) const;
    // Area of the region with the given parameter-space corners (3 or 4 of them).
    double region_area(const Vec2* uv, int count) const;
    // |dP/du x dP/dv| at uv: constant on triangles, affine in (u, v) on planar quads.
    double jacobian(const Vec2& uv) const { return m_jacobian.dot(Vec3(1, uv.x(), uv.y())); }
    // A quad whose bilinear map is affine (rectangles among them): uniform (u, v) is uniform
    // by area.
    bool is_parallelogram() const { return is_quad() && m_jacobian[1] == 0 && m_jacobian[2] == 0; }

private:
    // Cached by finalize(): the patch-plane frame and the map's edge vectors in it.
    Vec3 m_axis_x{1, 0, 0}, m_axis_y{0, 1, 0};
    Vec3 m_jacobian{0, 0, 0};                // J(u, v) = c0 + c1 u + c2 v
    Vec2 m_e1{1, 0}, m_e2{0, 1}, m_g{0, 0};  // quads: e2 is corner 3 - corner 0
};
// A million patches are 256 MB: the material is an index, and the 16-byte aligned 2D vectors
// come last, after 208 bytes, so that no padding is needed (320 bytes with both).
static_assert(sizeof(Patch) == 256);

struct PatchMaterial {
    Rgb reflectance = Rgb::Zero();
    Rgb emission = Rgb::Zero();  // emitted radiosity E, W/m^2
};

// The patches of a mesh in face order, their materials, and the scene constants the oracles
// need.
struct PatchSet {
    std::vector<Patch> patches;
    std::vector<PatchMaterial> materials{PatchMaterial{}};  // patches name them by index
    double total_area = 0;          // A_T
    double max_emitted_power = 0;   // Phi_max: largest A_i * max_c E_i,c of any patch
    Rgb emitted_power = Rgb::Zero();  // sum of A_i * E_i

    const Rgb& reflectance(const Patch& p) const { return materials[p.material].reflectance; }
    const Rgb& emission(const Patch& p) const { return materials[p.material].emission; }
};

PatchSet build_patch_set(const PatchMesh& mesh);

}  // namespace hmcr
