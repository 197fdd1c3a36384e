// SPDX-License-Identifier: Apache-2.0
// Ray queries against a ShadedMesh's Gouraud shading: the renderer's primary rays and the
// object-space error's point lookups both ask "what radiosity does the mesh show here".
//
// The polygons are cut into triangles that meet their neighbours edge to edge
// (viz/cell_triangles.h), so that Embree's watertight tests (the soup is built robust,
// rays/embree_scene.h) let no ray pass between cells. Within a triangle the radiosity is the
// barycentric interpolation of the point radiosity of its three points: Gouraud shading as a
// rasteriser would draw it. On a higher-order basis it is the cell's leaf polynomial, exactly,
// at the leaf's local coordinates of the hit: their barycentric interpolation between the
// triangle's points, exact where the patch's map is affine (triangles, parallelograms), with
// barycentric weights found again in double precision (Embree's are floats).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "common/types.h"
#include "radiosity/shaded_mesh.h"
#include "rays/embree_scene.h"
#include "viz/cell_triangles.h"

namespace hmcr {

struct ShadedHit {
    std::uint32_t cell = 0;       // the ShadedMesh cell hit
    Rgb radiosity = Rgb::Zero();  // the value shown at the hit, W/m^2
    double distance = 0;          // along the unit direction
    // Whether the ray meets the side the cell shows. A ray from behind a one-sided patch meets
    // its front's cell from behind, a side that is black; a two-sided patch's back cell is found
    // instead of its front's.
    bool facing = true;
};

// The side a cell shows (a mesh without the array shows fronts only).
inline std::uint8_t cell_side(const ShadedMesh& mesh, std::size_t cell) {
    return mesh.side.empty() ? kFront : mesh.side[cell];
}

class ShadedTracer {
public:
    // Copies what it needs: the mesh may be destroyed afterwards.
    explicit ShadedTracer(const ShadedMesh& mesh);

    // First hit along a unit direction (either side of a surface), or nullopt on a miss.
    std::optional<ShadedHit> hit_along(const Vec3& origin, const Vec3& direction) const;
    // What a camera sees there: the hit's radiosity, 0 on a side that is black.
    std::optional<Rgb> radiosity_along(const Vec3& origin, const Vec3& direction) const;
    std::optional<std::uint32_t> cell_along(const Vec3& origin, const Vec3& direction) const;

    double offset() const { return m_scene->offset(); }  // Embree's self-hit offset, metres

private:
    std::optional<ShadedHit> shade(const std::vector<CellTriangle>& triangles,
                                   const TriangleHit& hit, const Vec3& origin,
                                   const Vec3& direction) const;

    // The fronts' cells in one scene, the backs' (if any) in another: a back cell lies on its
    // front's, and a ray that meets a two-sided front from behind asks the backs' scene.
    std::vector<CellTriangle> m_triangles, m_back_triangles;
    std::vector<Rgb> m_point_radiosity;
    // A higher-order basis's: the points' local coordinates, the cells' coefficients and
    // whether each cell is a quad's (empty on the constant basis).
    Basis m_basis = Basis::constant;
    std::vector<Vec2> m_leaf_coordinates;
    std::vector<Vec3> m_points;
    std::vector<double> m_coefficients;
    std::size_t m_stride = 0;
    std::vector<std::uint8_t> m_quad_cell;
    std::vector<std::uint8_t> m_two_sided;  // by patch id
    std::vector<int> m_patch_of_cell;
    std::unique_ptr<EmbreeScene> m_scene, m_back_scene;
};

}  // namespace hmcr
