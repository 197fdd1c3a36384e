// SPDX-License-Identifier: Apache-2.0
// Small scenes built in code for the solver tests: boxes, plates, tessellated spheres.
#pragma once

#include <vector>

#include "common/types.h"
#include "meshes/patch_mesh.h"
#include "meshes/scene.h"

namespace hmcr::test {

struct TestPolygon {
    std::vector<Vec3> corners;  // counter-clockwise seen from the front
    Rgb reflectance = Rgb::Zero();
    Rgb emission = Rgb::Zero();  // radiosity E, W/m^2
    Rgb specular = Rgb::Zero();  // the path tracer's mirror (roughness 0) or glossy lobe
    double roughness = 0;
    // A back side with its own material, or none (the back is black and absorbing).
    bool two_sided = false;
    Rgb back_reflectance = Rgb::Zero();
    Rgb back_emission = Rgb::Zero();
    Rgb back_specular = Rgb::Zero();  // the back's mirror (the path tracer's alone)
};

// A PatchMesh with the hmcr:* properties (the back materials only if a polygon is two-sided);
// vertices with equal positions are shared.
PatchMesh make_patch_mesh(const std::vector<TestPolygon>& polygons);

// Axis-aligned rectangle in the plane `axis` = value, spanning [lo, hi] in the other two
// coordinates (cyclic order), facing +axis when `positive`.
TestPolygon axis_rectangle(int axis, double value, const Vec2& lo, const Vec2& hi, bool positive);

// The solver tests' plates: a unit square emitter (rho 0, E 1) at z = 0 facing up, and 1 m above
// it a unit square receiver of reflectance rho facing down, whose B is rho E F.
PatchMesh unit_plates(double rho);

// The six faces of the box [lo, hi], facing inward, each split into n x n quads.
std::vector<TestPolygon> inward_box(const Vec3& lo, const Vec3& hi, int n, const Rgb& rho,
                                    const Rgb& emission);

// A square view of `size` pixels from `position` towards `look_at` with `fov` degrees: up is +y,
// or +z when the view looks more than half a unit up or down (where +y would be nearly along it).
View test_view(const Vec3& position, const Vec3& look_at, double fov, int size);

// Icosahedron subdivided `level` times and projected on the sphere; faces point inward.
std::vector<TestPolygon> inward_icosphere(int level, double radius, const Rgb& rho);

// Triangles and quads in one mesh: the unit icosphere (level 2) around the box [-0.3, 0.3]^3
// of 2 x 2 quads a face, which blocks segments across the sphere. Grey, no light.
PatchMesh sphere_around_box();

}  // namespace hmcr::test
