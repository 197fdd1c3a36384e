// SPDX-License-Identifier: Apache-2.0
// Small hand-built patch meshes and checks shared by the viz tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <memory>
#include <vector>

#include "meshes/patch_mesh.h"
#include "radiosity/hierarchy.h"
#include "radiosity/shaded_mesh.h"
#include "rays/patch.h"

namespace hmcr::test {

// A patch mesh from points and faces (indices into the points), with grey material.
inline PatchMesh make_mesh(const std::vector<Vec3>& points,
                           std::initializer_list<std::vector<int>> faces) {
    PatchMesh mesh;
    std::vector<PatchMesh::VertexHandle> v;
    for (const Vec3& p : points) v.push_back(mesh.add_vertex({p.x(), p.y(), p.z()}));
    for (const auto& f : faces) {
        std::vector<PatchMesh::VertexHandle> fv;
        for (int i : f) fv.push_back(v[i]);
        EXPECT_TRUE(mesh.add_face(fv).is_valid());
    }
    (*materials_prop(mesh)).push_back({{0.5, 0.5, 0.5}, {0, 0, 0}});
    auto material = material_prop(mesh);
    for (auto f : mesh.faces()) material[f] = 0;
    return mesh;
}

// Mesh and hierarchy together; the hierarchy's limits allow deep subdivision. Not named Scene:
// a test in namespace hmcr::test that means hmcr::Scene may share a unity batch with this file.
struct MeshHierarchy {
    PatchMesh mesh;
    std::unique_ptr<Hierarchy> h;

    explicit MeshHierarchy(PatchMesh m) : mesh(std::move(m)) {
        h = std::make_unique<Hierarchy>(build_patch_set(mesh), HierarchyLimits{0, 24});
    }
    Element& root(int patch) { return h->root(patch); }
    // The element reached from the patch root by the child indices in `path`, subdividing.
    Element& at(int patch, std::initializer_list<int> path) {
        Element* e = &root(patch);
        for (int k : path) e = &h->subdivide(*e)[k];
        return *e;
    }
    // Calls f(Element&) on every leaf of the patch.
    template <class F>
    void for_leaves(int patch, F f) {
        auto visit = [&](const Element& e) { f(const_cast<Element&>(e)); };
        Hierarchy::visit_leaves(root(patch), visit);
    }
    ShadedMesh shade(double crease = 30) const { return build_shaded_mesh(*h, crease); }
};

// Unit square in z = 0 (patch 0) and, sharing its edge x = 1, either the square [1,2]x[0,1]
// (coplanar) or the square x = 1, z in [0,1] (a wall at a right angle).
inline PatchMesh two_quads(bool coplanar) {
    std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    if (coplanar) {
        p.insert(p.end(), {Vec3(2, 0, 0), Vec3(2, 1, 0)});
    } else {
        p.insert(p.end(), {Vec3(1, 0, 1), Vec3(1, 1, 1)});
    }
    return make_mesh(p, {{0, 1, 2, 3}, {2, 1, 4, 5}});
}

// The unit square split along its diagonal into two triangles.
inline PatchMesh two_triangles() {
    return make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
}

inline Vec3 point_of(const ShadedMesh& m, std::int64_t cell, std::int64_t i) {
    const auto n = m.offsets[cell + 1] - m.offsets[cell];
    return m.points[m.connectivity[m.offsets[cell] + (i % n + n) % n]];
}

// Vector area of a planar polygon (Newell); its norm is the area.
inline Vec3 polygon_area(const ShadedMesh& m, std::int64_t cell) {
    Vec3 a = Vec3::Zero();
    const auto n = m.offsets[cell + 1] - m.offsets[cell];
    for (std::int64_t i = 0; i < n; ++i) a += point_of(m, cell, i).cross(point_of(m, cell, i + 1));
    return 0.5 * a;
}

// No point lies strictly inside an edge of any polygon (the no-T-junction property).
inline testing::AssertionResult conforming(const ShadedMesh& m) {
    constexpr double kTol = 1e-12;  // points are exact dyadic fractions of unit-sized scenes
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        const auto n = m.offsets[c + 1] - m.offsets[c];
        for (std::int64_t i = 0; i < n; ++i) {
            const Vec3 a = point_of(m, c, i), b = point_of(m, c, i + 1);
            for (const Vec3& p : m.points) {
                const double t = (p - a).dot(b - a) / (b - a).squaredNorm();
                if (t <= kTol || t >= 1 - kTol) continue;
                if ((a + t * (b - a) - p).norm() < kTol) {
                    return testing::AssertionFailure() << "point (" << p.transpose()
                                                       << ") inside edge " << i << " of cell " << c;
                }
            }
        }
    }
    return testing::AssertionSuccess();
}

// Indices of the points at position x.
inline std::vector<std::size_t> points_at(const ShadedMesh& m, const Vec3& x) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < m.points.size(); ++i) {
        if ((m.points[i] - x).norm() < 1e-12) out.push_back(i);
    }
    return out;
}

}  // namespace hmcr::test
