// Small scenes built in code for the solver tests: boxes, plates, tessellated spheres.
#pragma once

#include <vector>

#include "meshes/patch_mesh.h"
#include "common/types.h"

namespace hmcr::test {

struct TestPolygon {
    std::vector<Vec3> corners;  // counter-clockwise seen from the front
    Rgb reflectance = Rgb::Zero();
    Rgb emission = Rgb::Zero();  // radiosity E, W/m^2
};

// A PatchMesh with the hmcr:* properties; vertices with equal positions are shared.
PatchMesh make_patch_mesh(const std::vector<TestPolygon>& polygons);

// Axis-aligned rectangle in the plane `axis` = value, spanning [lo, hi] in the other two
// coordinates (cyclic order), facing +axis when `positive`.
TestPolygon axis_rectangle(int axis, double value, const Vec2& lo, const Vec2& hi, bool positive);

// The six faces of the box [lo, hi], facing inward, each split into n x n quads.
std::vector<TestPolygon> inward_box(const Vec3& lo, const Vec3& hi, int n, const Rgb& rho,
                                    const Rgb& emission);

// Icosahedron subdivided `level` times and projected on the sphere; faces point inward.
std::vector<TestPolygon> inward_icosphere(int level, double radius, const Rgb& rho);

}  // namespace hmcr::test
