// SPDX-License-Identifier: Apache-2.0
#include "studies/solution_probe.h"

#include <algorithm>
#include <array>

#include "radiosity/polynomial_mesh.h"

namespace hmcr {
namespace {

// The closest point of triangle (a, b, c) to p as barycentric weights of b and c (Ericson,
// Real-Time Collision Detection, 5.1.5: the Voronoi regions of vertices, edges and face).
Vec2 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return {0, 0};
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return {1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return {d1 / (d1 - d3), 0};
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return {0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return {0, d2 / (d2 - d6)};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {1 - w, w};
    }
    const double denominator = va + vb + vc;
    return {vb / denominator, vc / denominator};
}

}  // namespace

SolutionProbe::SolutionProbe(const ShadedTracer& t, const ShadedMesh& s)
    : m_tracer(t), m_solution(s), m_delta(10 * t.offset()) {
    std::size_t keys = 0;
    for (std::size_t c = 0; c < s.cell_count(); ++c) {
        keys = std::max(keys, key(s.patch_id[c], cell_side(s, c)) + 1);
    }
    m_first.assign(keys + 1, 0);
    for (std::size_t c = 0; c < s.cell_count(); ++c)
        ++m_first[key(s.patch_id[c], cell_side(s, c)) + 1];
    for (std::size_t k = 0; k < keys; ++k) m_first[k + 1] += m_first[k];
    m_cells.resize(s.cell_count());
    std::vector<std::size_t> next(m_first.begin(), m_first.end() - 1);
    for (std::size_t c = 0; c < s.cell_count(); ++c) {
        m_cells[next[key(s.patch_id[c], cell_side(s, c))]++] = c;
    }
}

bool SolutionProbe::covers(int patch, std::uint8_t side) const {
    const std::size_t k = key(patch, side);
    return k + 1 < m_first.size() && m_first[k + 1] > m_first[k];
}

std::optional<Rgb> SolutionProbe::at(const Vec3& p, const Vec3& normal, int patch,
                                     std::uint8_t side, bool& by_ray) const {
    by_ray = true;
    for (const double from : {1.0, -1.0}) {
        const auto hit = m_tracer.hit_along(p + from * m_delta * normal, -from * normal);
        if (hit && m_solution.patch_id[hit->cell] == patch &&
            cell_side(m_solution, hit->cell) == side) {
            return hit->radiosity;
        }
    }
    by_ray = false;
    return nearest(p, patch, side);
}

SolutionProbe::Value SolutionProbe::value(const Vec3& p, const Vec3& normal, int patch,
                                          std::uint8_t side, const Rgb& emission) const {
    if (!covers(patch, side) && covers(patch, std::uint8_t(1 - side))) {
        return {emission, Found::unlit};
    }
    bool by_ray = true;
    const std::optional<Rgb> b = at(p, normal, patch, side, by_ray);
    if (!b) return {Rgb::Zero(), Found::unmatched};
    return {*b, by_ray ? Found::ray : Found::nearest};
}

// What the solution shows (radiosity_at) at the closest point of the patch side's cells
// within delta of p: a point at an edge between patches, which the tracer's float arithmetic may
// put on the neighbour (a light tile in a ceiling), is still its own patch's.
std::optional<Rgb> SolutionProbe::nearest(const Vec3& p, int patch, std::uint8_t side) const {
    const std::size_t k = key(patch, side);
    if (k + 1 >= m_first.size()) return std::nullopt;
    double best = m_delta * m_delta;
    // The closest point found so far: its cell, triangle and weights, valued once at the end.
    std::optional<std::size_t> cell;
    std::array<std::size_t, 3> points{};
    Vec2 weights(0, 0);
    const ShadedMesh& s = m_solution;
    for (std::size_t i = m_first[k]; i < m_first[k + 1]; ++i) {
        const std::size_t c = m_cells[i];
        const auto v0 = s.offsets[c], end = s.offsets[c + 1];
        const auto corner = [&](std::int64_t at) { return std::size_t(s.connectivity[at]); };
        for (auto at = v0 + 1; at + 1 < end; ++at) {
            const Vec3 &a = s.points[corner(v0)], &b = s.points[corner(at)],
                       &d = s.points[corner(at + 1)];
            const Vec2 w = closest_on_triangle(p, a, b, d);
            const Vec3 q = (1 - w.x() - w.y()) * a + w.x() * b + w.y() * d;
            const double distance = (q - p).squaredNorm();
            if (distance >= best) continue;
            best = distance;
            cell = c;
            points = {corner(v0), corner(at), corner(at + 1)};
            weights = w;
        }
    }
    if (!cell) return std::nullopt;
    return radiosity_at(s, *cell, points, weights.x(), weights.y());
}

}  // namespace hmcr
