// SPDX-License-Identifier: Apache-2.0
#include "tests/support/test_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace hmcr::test {

PatchMesh make_patch_mesh(const std::vector<TestPolygon>& polygons) {
    PatchMesh mesh;
    std::vector<FaceMaterial>& table = *materials_prop(mesh);
    auto material = material_prop(mesh);
    auto line = source_line_prop(mesh);
    std::map<std::array<double, 3>, PatchMesh::VertexHandle> welded;
    for (const TestPolygon& p : polygons) {
        std::vector<PatchMesh::VertexHandle> vs;
        for (const Vec3& c : p.corners) {
            const std::array<double, 3> key{c.x(), c.y(), c.z()};
            auto it = welded.find(key);
            if (it == welded.end()) {
                it = welded.emplace(key, mesh.add_vertex({c.x(), c.y(), c.z()})).first;
            }
            vs.push_back(it->second);
        }
        auto f = mesh.add_face(vs);
        if (!f.is_valid()) {  // non-manifold configuration: give the face its own vertices
            for (auto& v : vs) v = mesh.add_vertex(mesh.point(v));
            f = mesh.add_face(vs);
        }
        material[f] = std::uint32_t(table.size());
        table.push_back({{p.reflectance[0], p.reflectance[1], p.reflectance[2]},
                         {p.emission[0], p.emission[1], p.emission[2]},
                         {p.specular[0], p.specular[1], p.specular[2]},
                         p.roughness});
        line[f] = 0;
    }
    const bool any_back = std::any_of(polygons.begin(), polygons.end(),
                                      [](const TestPolygon& p) { return p.two_sided; });
    if (!any_back) return mesh;
    auto back = back_material_prop(mesh);
    for (auto f : mesh.faces()) {
        const TestPolygon& p = polygons[std::size_t(f.idx())];
        back[f] = kOneSided;
        if (!p.two_sided) continue;
        back[f] = std::uint32_t(table.size());
        table.push_back({{p.back_reflectance[0], p.back_reflectance[1], p.back_reflectance[2]},
                         {p.back_emission[0], p.back_emission[1], p.back_emission[2]},
                         {p.back_specular[0], p.back_specular[1], p.back_specular[2]}});
    }
    return mesh;
}

View test_view(const Vec3& position, const Vec3& look_at, double fov, int size) {
    View v;
    v.name = "test";
    v.position = position;
    v.look_at = look_at;
    v.up = std::abs(look_at.y() - position.y()) > 0.5 ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    v.fov_degrees = fov;
    v.width = v.height = size;
    return v;
}

TestPolygon axis_rectangle(int axis, double value, const Vec2& lo, const Vec2& hi, bool positive) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // e_a x e_b = e_axis
    auto at = [&](double s, double t) {
        Vec3 p;
        p[axis] = value;
        p[a] = s;
        p[b] = t;
        return p;
    };
    TestPolygon poly;
    poly.corners = {at(lo.x(), lo.y()), at(hi.x(), lo.y()), at(hi.x(), hi.y()), at(lo.x(), hi.y())};
    if (!positive) std::swap(poly.corners[1], poly.corners[3]);
    return poly;
}

PatchMesh unit_plates(double rho) {
    TestPolygon emitter = axis_rectangle(2, 0, {0, 0}, {1, 1}, true);
    emitter.emission = Rgb::Constant(1);
    TestPolygon receiver = axis_rectangle(2, 1, {0, 0}, {1, 1}, false);
    receiver.reflectance = Rgb::Constant(rho);
    return make_patch_mesh({emitter, receiver});
}

std::vector<TestPolygon> inward_box(const Vec3& lo, const Vec3& hi, int n, const Rgb& rho,
                                    const Rgb& emission) {
    std::vector<TestPolygon> faces;
    for (int axis = 0; axis < 3; ++axis) {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) {
                    auto cut = [&](int k, int c) { return lo[k] + (hi[k] - lo[k]) * c / n; };
                    TestPolygon p =
                        axis_rectangle(axis, side ? hi[axis] : lo[axis], {cut(a, i), cut(b, j)},
                                       {cut(a, i + 1), cut(b, j + 1)}, side == 0);
                    p.reflectance = rho;
                    p.emission = emission;
                    faces.push_back(p);
                }
            }
        }
    }
    return faces;
}

std::vector<TestPolygon> inward_icosphere(int level, double radius, const Rgb& rho) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<int, 3>> f = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& p : v) p.normalize();
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back((v[a] + v[b]).normalized());
            return mid[key] = int(v.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& [a, b, c] : f) {
            const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        f = std::move(next);
    }
    std::vector<TestPolygon> faces;
    for (const auto& [a, b, c] : f) {
        TestPolygon p;
        p.corners = {radius * v[a], radius * v[c], radius * v[b]};  // reversed: facing inward
        p.reflectance = rho;
        faces.push_back(p);
    }
    return faces;
}

PatchMesh sphere_around_box() {
    std::vector<TestPolygon> polys = inward_icosphere(2, 1.0, Rgb::Constant(0.5));
    for (const TestPolygon& p : inward_box(Vec3(-0.3, -0.3, -0.3), Vec3(0.3, 0.3, 0.3), 2,
                                           Rgb::Constant(0.5), Rgb::Zero())) {
        polys.push_back(p);
    }
    return make_patch_mesh(polys);
}

}  // namespace hmcr::test
