// SPDX-License-Identifier: Apache-2.0
#include "viz/shaded_tracer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "radiosity/polynomial_mesh.h"

namespace hmcr {
namespace {

std::vector<std::array<unsigned, 3>> point_triples(const std::vector<CellTriangle>& triangles) {
    std::vector<std::array<unsigned, 3>> out;
    out.reserve(triangles.size());
    for (const CellTriangle& t : triangles) out.push_back({t.points[0], t.points[1], t.points[2]});
    return out;
}

// The weights of the triangle's second and third point at the ray's meeting with its plane, in
// double precision; Embree's own (single precision, about 1e-7) where the ray runs along it.
std::array<double, 2> exact_barycentrics(const std::array<Vec3, 3>& p, const Vec3& origin,
                                         const Vec3& direction, const TriangleHit& hit) {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], n = e1.cross(e2);
    const double along = n.dot(direction), nn = n.squaredNorm();
    if (!(std::abs(along) > 1e-12 * std::sqrt(nn)) || !(nn > 0)) return {hit.u, hit.v};
    const Vec3 x = origin + (n.dot(p[0] - origin) / along) * direction - p[0];
    return {x.cross(e2).dot(n) / nn, e1.cross(x).dot(n) / nn};
}

}  // namespace

ShadedTracer::ShadedTracer(const ShadedMesh& mesh)
    : m_triangles(triangulate_cells(mesh)), m_point_radiosity(mesh.point_radiosity) {
    if (mesh.basis != Basis::constant) {
        if (mesh.leaf_coordinates.size() != mesh.points.size() ||
            mesh.coefficients.size() != mesh.cell_stride() * mesh.cell_count()) {
            throw std::invalid_argument(
                "ShadedMesh needs local coordinates per point and coefficients per cell");
        }
        m_basis = mesh.basis;
        m_leaf_coordinates = mesh.leaf_coordinates;
        m_points = mesh.points;
        m_coefficients = mesh.coefficients;
        m_stride = mesh.cell_stride();
        m_quad_cell.resize(mesh.cell_count());
        for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
            m_quad_cell[c] = mesh.offsets[c + 1] - mesh.offsets[c] == 4;
        }
    }
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
        if (cell_side(mesh, c) != kBack) continue;
        const auto patch = std::size_t(mesh.patch_id[c]);
        if (m_two_sided.size() <= patch) m_two_sided.resize(patch + 1, 0);
        m_two_sided[patch] = 1;
    }
    if (!m_two_sided.empty()) {
        m_patch_of_cell = mesh.patch_id;
        const auto back = std::stable_partition(
            m_triangles.begin(), m_triangles.end(),
            [&](const CellTriangle& t) { return cell_side(mesh, t.cell) == kFront; });
        m_back_triangles.assign(back, m_triangles.end());
        m_triangles.erase(back, m_triangles.end());
        m_back_scene = std::make_unique<EmbreeScene>(mesh.points, point_triples(m_back_triangles));
    }
    m_scene = std::make_unique<EmbreeScene>(mesh.points, point_triples(m_triangles));
}

std::optional<ShadedHit> ShadedTracer::shade(const std::vector<CellTriangle>& triangles,
                                             const TriangleHit& hit, const Vec3& origin,
                                             const Vec3& direction) const {
    const CellTriangle& t = triangles[hit.triangle];
    // Embree's (u, v) weigh the triangle's second and third vertex.
    const double w0 = 1 - hit.u - hit.v;
    Rgb b;
    if (m_basis == Basis::constant) {
        b = w0 * m_point_radiosity[t.points[0]] + hit.u * m_point_radiosity[t.points[1]] +
            hit.v * m_point_radiosity[t.points[2]];
    } else {
        const auto [u, v] = exact_barycentrics(
            {m_points[t.points[0]], m_points[t.points[1]], m_points[t.points[2]]}, origin,
            direction, hit);
        const Vec2 ab = (1 - u - v) * m_leaf_coordinates[t.points[0]] +
                        u * m_leaf_coordinates[t.points[1]] + v * m_leaf_coordinates[t.points[2]];
        b = polynomial_radiosity(m_basis, m_quad_cell[t.cell] != 0,
                                 m_coefficients.data() + m_stride * t.cell, ab);
    }
    return ShadedHit{t.cell, b, hit.distance, hit.normal.dot(direction) < 0};
}

std::optional<ShadedHit> ShadedTracer::hit_along(const Vec3& origin, const Vec3& direction) const {
    const std::optional<TriangleHit> hit = m_scene->first_hit_triangle(origin, direction);
    if (!hit) return std::nullopt;
    std::optional<ShadedHit> out = shade(m_triangles, *hit, origin, direction);
    if (out->facing || !m_back_scene) return out;
    const auto patch = std::size_t(m_patch_of_cell[out->cell]);
    if (patch >= m_two_sided.size() || !m_two_sided[patch]) return out;
    // The back cell on the same plane, as far as the front's within the self-hit offset.
    const std::optional<TriangleHit> back = m_back_scene->first_hit_triangle(origin, direction);
    if (back && back->distance <= hit->distance + m_scene->offset()) {
        return shade(m_back_triangles, *back, origin, direction);
    }
    return out;
}

std::optional<Rgb> ShadedTracer::radiosity_along(const Vec3& origin, const Vec3& direction) const {
    const auto hit = hit_along(origin, direction);
    if (!hit) return std::nullopt;
    return hit->facing ? hit->radiosity : Rgb(Rgb::Zero());
}

std::optional<std::uint32_t> ShadedTracer::cell_along(const Vec3& origin,
                                                      const Vec3& direction) const {
    const auto hit = hit_along(origin, direction);
    if (!hit) return std::nullopt;
    return hit->cell;
}

}  // namespace hmcr
