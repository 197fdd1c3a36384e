// SPDX-License-Identifier: Apache-2.0
#include "rays/patch.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hmcr {
namespace {

Vec2 clamp_to_unit(const Vec2& uv) { return uv.cwiseMax(0.0).cwiseMin(1.0); }

// Inverse of the bilinear map, in 2D plane coordinates: q = u e1 + v e3 + u v g.
// Eliminating v gives a quadratic in u (zero leading term for parallelograms).
Vec2 inverse_bilinear(const Vec2& q, const Vec2& e1, const Vec2& e3, const Vec2& g) {
    const double a = -cross2(e1, g);
    const double b = cross2(q, g) - cross2(e1, e3);
    const double c = cross2(q, e3);
    double u;
    if (std::abs(a) < 1e-12 * (std::abs(b) + std::abs(c)) || a == 0) {
        u = -c / b;
    } else {
        const double disc = std::sqrt(std::max(0.0, b * b - 4 * a * c));
        // Stable roots; keep the one inside (or nearest to) [0, 1].
        const double qq = -0.5 * (b + std::copysign(disc, b));
        const double r1 = qq / a, r2 = c / qq;
        auto dist = [](double x) { return x < 0 ? -x : (x > 1 ? x - 1 : 0); };
        u = dist(r1) <= dist(r2) ? r1 : r2;
    }
    const Vec2 d = e3 + u * g;
    const double v = (q - u * e1).dot(d) / d.squaredNorm();
    return clamp_to_unit({u, v});
}

}  // namespace

Vec3 Patch::point(const Vec2& uv) const {
    const double u = uv.x(), v = uv.y();
    if (!is_quad()) return corner[0] + u * (corner[1] - corner[0]) + v * (corner[2] - corner[0]);
    return (1 - u) * (1 - v) * corner[0] + u * (1 - v) * corner[1] + u * v * corner[2] +
           (1 - u) * v * corner[3];
}

void Patch::finalize() {
    const Vec3 n = is_quad() ? Vec3((corner[2] - corner[0]).cross(corner[3] - corner[1]))
                             : Vec3((corner[1] - corner[0]).cross(corner[2] - corner[0]));
    normal = n.normalized();
    area = 0.5 * n.norm();
    m_axis_x = (corner[1] - corner[0]).normalized();
    const Vec3 axis_y = normal.cross(m_axis_x);
    auto to2 = [&](const Vec3& w) { return Vec2(w.dot(m_axis_x), w.dot(axis_y)); };
    m_e1 = to2(corner[1] - corner[0]);
    m_parallelogram = false;
    if (!is_quad()) {
        m_e2 = to2(corner[2] - corner[0]);
        return;
    }
    m_e2 = to2(corner[3] - corner[0]);
    m_g = to2(corner[0] - corner[1] + corner[2] - corner[3]);
    // (Numerically) parallelograms: the linear terms of the Jacobian are taken as zero.
    m_parallelogram = m_g.norm() <= 1e-12 * (m_e1.norm() + m_e2.norm());
}

Vec2 Patch::param(const Vec3& p) const {
    const Vec3 w = p - corner[0];
    const Vec2 q(w.dot(m_axis_x), w.dot(normal.cross(m_axis_x)));
    if (is_quad()) return inverse_bilinear(q, m_e1, m_e2, m_g);
    const double det = cross2(m_e1, m_e2);
    Vec2 uv(cross2(q, m_e2) / det, cross2(m_e1, q) / det);
    uv = uv.cwiseMax(0.0);
    const double s = uv.sum();
    return s > 1 ? Vec2(uv / s) : uv;
}

Vec2f Patch::param_of_hit(bool second_triangle, float b1, float b2, const Vec3& p) const {
    if (!is_quad()) return {b1, b2};
    if (!m_parallelogram) return param(p).cast<float>();
    // corner 2 = corner 0 + e1 + e3: the triangle (0, 1, 2) maps (b1, b2) to (b1 + b2, b2),
    // the triangle (0, 2, 3) to (b1, b1 + b2).
    const float sum = std::min(1.0f, b1 + b2);
    return second_triangle ? Vec2f(b1, sum) : Vec2f(sum, b2);
}

double Patch::region_area(const Vec2* uv, int count) const {
    const Vec3 a = point(uv[0]), b = point(uv[1]), c = point(uv[2]);
    if (count == 3) return 0.5 * (b - a).cross(c - a).norm();
    const Vec3 d = point(uv[3]);
    return 0.5 * (c - a).cross(d - b).norm();  // exact for planar quads
}

PatchSet build_patch_set(const PatchMesh& mesh) {
    PatchSet set;
    const FaceMaterials materials(mesh);
    set.materials.clear();
    for (const FaceMaterial& m : materials.table()) {
        set.materials.push_back({Rgb(m.reflectance[0], m.reflectance[1], m.reflectance[2]),
                                 Rgb(m.emission[0], m.emission[1], m.emission[2]),
                                 Rgb(m.specular[0], m.specular[1], m.specular[2]), m.roughness});
    }
    set.vertices = face_vertices(mesh);
    set.patches.reserve(mesh.n_faces());
    for (auto f : mesh.faces()) {
        Patch p;
        p.corner_count = std::uint8_t(set.vertices.corner_count(f.idx()));
        const auto& corners = set.vertices.faces[f.idx()];
        for (int k = 0; k < p.corner_count; ++k) {
            const auto& pt = mesh.point(PatchMesh::VertexHandle(int(corners[k])));
            p.corner[k] = Vec3(pt[0], pt[1], pt[2]);
        }
        p.finalize();
        p.material = materials.index(f);
        set.patches.push_back(p);
        const std::uint32_t back = materials.back_index(f);
        if (back != kOneSided && set.back_materials.empty()) {
            set.back_materials.assign(mesh.n_faces(), kOneSided);
        }
        if (!set.back_materials.empty()) set.back_materials[std::size_t(f.idx())] = back;
    }
    for (std::size_t i = 0; i < set.patches.size(); ++i) {
        for (const std::uint8_t side : {kFront, kBack}) {
            if (side == kBack && !set.two_sided(i)) continue;
            const double area = set.patches[i].area;
            const Rgb& emission = set.material(i, side).emission;
            set.total_area += area;
            set.emitted_power += area * emission;
            set.max_emitted_power = std::max(set.max_emitted_power, area * emission.maxCoeff());
        }
    }
    return set;
}

}  // namespace hmcr
