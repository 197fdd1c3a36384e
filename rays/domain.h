// SPDX-License-Identifier: Apache-2.0
// Parameter-space domain of an element and its regular 4-way subdivision (docs/design.md §2).
//
// On a quad patch the domain is the square [u0, u0+s] x [v0, v0+s]. On a triangle patch it is
// a triangle with legs of length |s| along u and v from the corner (u0, v0): upright (corners
// (u0,v0), (u0+s,v0), (u0,v0+s)) when s > 0, inverted (corners (u0,v0), (u0+s,v0), (u0,v0+s)
// with s < 0) for the middle children. All coordinates are dyadic, so floats hold them exactly
// down to depth 24.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "common/types.h"

namespace hmcr {

struct Domain {
    float u0 = 0, v0 = 0, s = 1;

    static Domain root() { return {}; }

    // Corners in parameter space, counter-clockwise like the patch's own corners.
    std::array<Vec2, 4> corners(bool quad) const {
        const double u = u0, v = v0, d = s;
        if (quad) return {Vec2(u, v), Vec2(u + d, v), Vec2(u + d, v + d), Vec2(u, v + d)};
        return {Vec2(u, v), Vec2(u + d, v), Vec2(u, v + d), Vec2(u, v)};
    }
    Vec2 centre(bool quad) const {
        return quad ? Vec2(u0 + 0.5 * s, v0 + 0.5 * s) : Vec2(u0 + s / 3.0, v0 + s / 3.0);
    }

    // Child k: quads number them (u half) + 2 (v half); triangles 0..2 are the corner
    // triangles at (u0,v0), along u, along v, and 3 is the middle one, of opposite orientation.
    Domain child(bool quad, int k) const {
        const float h = 0.5f * s;
        if (quad) return {u0 + (k & 1) * h, v0 + (k >> 1) * h, h};
        switch (k) {
            case 0:
                return {u0, v0, h};
            case 1:
                return {u0 + h, v0, h};
            case 2:
                return {u0, v0 + h, h};
            default:
                return {u0 + h, v0 + h, -h};
        }
    }

    // On a quad, the column (for u) or row (for v) of the 2^depth x 2^depth cells of the
    // subdivision at `depth` that child_containing leads to from the root: the leading binary
    // digits of x (x * 2^depth is exact), the first below the domain, the last from its far edge
    // on, and the first for NaN, where every comparison fails.
    static std::uint32_t quad_cell(double x, int depth) {
        const double n = double(std::uint32_t(1) << depth), c = x * n;
        if (!(c >= 0)) return 0;
        return c >= n ? std::uint32_t(n) - 1 : std::uint32_t(c);  // truncation is floor here
    }
    // The child taken at `level` levels above the cells on the way from the root to cell (i, j):
    // bit `level` of i says the u half, of j the v half (child's numbering).
    static int quad_cell_child(std::uint32_t i, std::uint32_t j, int level) {
        return int((i >> level) & 1) + 2 * int((j >> level) & 1);
    }
    // The quad's domain of cell (i, j) at `depth`.
    static Domain quad_cell_domain(std::uint32_t i, std::uint32_t j, int depth) {
        const float s = 1.0f / float(std::uint32_t(1) << depth);  // exact
        return {float(i) * s, float(j) * s, s};
    }

    // The local coordinates (a, b) = ((u - u0) / s, (v - v0) / s) of uv: the unit square's or
    // the unit triangle's, where an element's basis functions are defined (radiosity/basis.h).
    Vec2 local(const Vec2& uv) const { return {(uv.x() - u0) / s, (uv.y() - v0) / s}; }
    // The child containing (u, v) (a point of this domain).
    int child_containing(bool quad, const Vec2& uv) const {
        const Vec2 ab = local(uv);
        return child_at(quad, ab.x(), ab.y());
    }
    // The child containing the point at (a, b) = ((u - u0) / s, (v - v0) / s).
    static int child_at(bool quad, double a, double b) {
        if (quad) return (a >= 0.5 ? 1 : 0) + (b >= 0.5 ? 2 : 0);
        if (a >= 0.5) return 1;
        if (b >= 0.5) return 2;
        return a + b < 0.5 ? 0 : 3;
    }
};

// The children child_containing picks from the root down towards one point, without dividing:
// s is a power of two (its sign aside) at every depth, so (u - u0) times 1 / s, kept beside the
// domain, is the exact (u - u0) / s. For a walk down a tree a ray at a time
// (radiosity/leaf_index.h), where the divisions were most of a level's time.
class DomainWalk {
public:
    DomainWalk(bool quad, const Vec2& uv) : m_quad(quad), m_uv(uv) {}
    // The walk from `start`, a domain of the subdivision, as if it had come down to it.
    DomainWalk(bool quad, const Vec2& uv, const Domain& start)
        : m_quad(quad), m_uv(uv), m_domain(start), m_inverse(1 / double(start.s)) {}

    // The child of the current domain that holds the point; the walk goes into it.
    int step() {
        const int k = Domain::child_at(m_quad, (m_uv.x() - m_domain.u0) * m_inverse,
                                       (m_uv.y() - m_domain.v0) * m_inverse);
        m_domain = m_domain.child(m_quad, k);
        m_inverse = std::copysign(2 * m_inverse, double(m_domain.s));  // 1 / s, exactly
        return k;
    }

private:
    bool m_quad;
    Vec2 m_uv;
    Domain m_domain = Domain::root();
    double m_inverse = 1;
};

}  // namespace hmcr
