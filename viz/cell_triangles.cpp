// SPDX-License-Identifier: Apache-2.0
#include "viz/cell_triangles.h"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace hmcr {
namespace {

void check_cell(const ShadedMesh& mesh, std::size_t c) {
    const auto first = mesh.offsets[c], last = mesh.offsets[c + 1];
    if (first < 0 || last < first + 3 || last > std::int64_t(mesh.connectivity.size())) {
        throw std::invalid_argument("cell " + std::to_string(c) + " is not a polygon");
    }
    for (auto s = first; s < last; ++s) {
        const auto p = mesh.connectivity[s];
        if (p < 0 || p >= std::int64_t(mesh.points.size())) {
            throw std::invalid_argument("cell " + std::to_string(c) + " names point " +
                                        std::to_string(p) + " of " +
                                        std::to_string(mesh.points.size()));
        }
    }
}

// Whether the path a -> b -> c turns at b: the sine of the turn is above 1e-6. Points of a
// polygon's edge lie on it to rounding (1e-16 relative); a leaf's corners turn by degrees.
bool turns(const Vec3& a, const Vec3& b, const Vec3& c) {
    constexpr double kSine = 1e-6;
    const Vec3 u = b - a, v = c - b;
    return u.cross(v).squaredNorm() > kSine * kSine * u.squaredNorm() * v.squaredNorm();
}

// Clips one polygon's triangles. The tip of each ear is a corner (a point where the boundary
// turns) and what remains keeps three corners, so no triangle has zero area; the first such
// tip after the first point is taken, which on a polygon of corners only is the fan from it.
// One clipper serves all cells, so that its buffers are allocated once.
class EarClipper {
public:
    explicit EarClipper(const ShadedMesh& mesh) : m_mesh(mesh) {}

    void clip(std::uint32_t cell, std::vector<CellTriangle>& out) {
        m_ring.clear();
        for (auto s = m_mesh.offsets[cell]; s < m_mesh.offsets[cell + 1]; ++s) {
            m_ring.push_back(std::uint32_t(m_mesh.connectivity[s]));
        }
        m_corner.clear();
        m_corners = 0;
        for (std::size_t i = 0; i < m_ring.size(); ++i) {
            m_corner.push_back(corner_at(i));
            m_corners += m_corner.back();
        }
        while (m_ring.size() > 3) {
            const std::size_t tip = next_tip();
            if (tip == kNone) break;
            out.push_back({{m_ring[before(tip)], m_ring[tip], m_ring[after(tip)]}, cell});
            remove(tip);
        }
        // Three points left, or a polygon that is not convex: the fan of what remains.
        for (std::size_t i = 1; i + 1 < m_ring.size(); ++i) {
            out.push_back({{m_ring[0], m_ring[i], m_ring[i + 1]}, cell});
        }
    }

private:
    static constexpr std::size_t kNone = ~std::size_t(0);

    std::size_t before(std::size_t i) const { return (i + m_ring.size() - 1) % m_ring.size(); }
    std::size_t after(std::size_t i) const { return (i + 1) % m_ring.size(); }
    const Vec3& at(std::size_t i) const { return m_mesh.points[m_ring[i]]; }
    bool corner_at(std::size_t i) const { return turns(at(before(i)), at(i), at(after(i))); }

    // The corners left if the tip went: its neighbours' turns are all that change.
    int corners_without(std::size_t tip) const {
        const std::size_t p = before(tip), n = after(tip), pp = before(p), nn = after(n);
        return m_corners - m_corner[tip] - m_corner[p] - m_corner[n] + turns(at(pp), at(p), at(n)) +
               turns(at(p), at(n), at(nn));
    }

    std::size_t next_tip() const {
        for (std::size_t k = 1; k <= m_ring.size(); ++k) {
            const std::size_t i = k % m_ring.size();
            if (m_corner[i] && corners_without(i) >= 3) return i;
        }
        return kNone;
    }

    void remove(std::size_t tip) {
        m_corners -= m_corner[tip];
        m_ring.erase(m_ring.begin() + std::ptrdiff_t(tip));
        m_corner.erase(m_corner.begin() + std::ptrdiff_t(tip));
        const std::size_t n = tip % m_ring.size(), p = before(n);
        for (const std::size_t i : {p, n}) {
            m_corners += int(corner_at(i)) - int(m_corner[i]);
            m_corner[i] = corner_at(i);
        }
    }

    const ShadedMesh& m_mesh;
    std::vector<std::uint32_t> m_ring;  // the polygon's points not yet clipped
    std::vector<bool> m_corner;         // whether the ring turns at each
    int m_corners = 0;
};

}  // namespace

std::vector<CellTriangle> triangulate_cells(const ShadedMesh& mesh) {
    if (mesh.offsets.empty() || mesh.offsets.front() != 0) {
        throw std::invalid_argument("ShadedMesh offsets must start at 0");
    }
    if (mesh.point_radiosity.size() != mesh.points.size()) {
        throw std::invalid_argument("ShadedMesh needs one radiosity per point");
    }
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) check_cell(mesh, c);
    std::vector<CellTriangle> out;
    out.reserve(mesh.connectivity.size() - 2 * mesh.cell_count());
    EarClipper clipper(mesh);
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) clipper.clip(std::uint32_t(c), out);
    return out;
}

}  // namespace hmcr
