// SPDX-License-Identifier: Apache-2.0
#include "radiosity/conforming_polygons.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hmcr {
namespace {

constexpr std::int64_t kGrid = std::int64_t(1) << 24;  // grid steps per parameter unit

struct GridPoint {
    std::int64_t u = 0, v = 0;
};

// The mesh vertices and edges of one patch; edge k runs from corner k to corner k + 1.
struct PatchTopology {
    int corner_count = 0;
    std::array<std::uint32_t, 4> vertex{};
    std::array<std::uint32_t, 4> edge{};
    std::array<bool, 4> forward{};  // corner k has the lower vertex index of edge k
    bool quad() const { return corner_count == 4; }
};

// The patches' mesh vertices and edges, checked against the patches once.
class MeshTopology {
public:
    MeshTopology(const PatchSet& set, const FaceEdges& edges)
        : m_vertices(set.vertices), m_edges(edges) {
        if (m_vertices.faces.size() != set.patches.size()) {
            throw std::invalid_argument("shaded mesh: the patch set has the mesh vertices of " +
                                        std::to_string(m_vertices.faces.size()) + " faces for " +
                                        std::to_string(set.patches.size()) + " patches");
        }
        for (std::size_t f = 0; f < set.patches.size(); ++f) {
            if (m_vertices.corner_count(f) != set.patches[f].corner_count) {
                throw std::invalid_argument("shaded mesh: face " + std::to_string(f) +
                                            " does not match its patch");
            }
        }
        if (m_edges.faces.size() != m_vertices.faces.size()) {
            throw std::invalid_argument("shaded mesh: the edges are not the patches' own");
        }
    }
    std::uint32_t vertex_count() const { return m_vertices.vertex_count; }
    PatchTopology operator[](std::uint32_t patch) const {
        PatchTopology t;
        const auto& v = m_vertices.faces[patch];
        t.corner_count = m_vertices.corner_count(patch);
        t.vertex = v;
        t.edge = m_edges.faces[patch];
        for (int k = 0; k < t.corner_count; ++k) t.forward[k] = v[k] < v[(k + 1) % t.corner_count];
        return t;
    }

private:
    const FaceVertices& m_vertices;
    const FaceEdges& m_edges;
};

// Position along patch edge k, measured from corner k, of a grid point on that edge.
std::int64_t along_edge(bool quad, int k, GridPoint p) {
    switch (k) {
        case 0:
            return p.u;
        case 1:
            return p.v;
        case 2:
            return quad ? kGrid - p.u : kGrid - p.v;
        default:
            return kGrid - p.v;
    }
}

// Inverse of along_edge.
GridPoint on_edge(bool quad, int k, std::int64_t t) {
    switch (k) {
        case 0:
            return {t, 0};
        case 1:
            return quad ? GridPoint{kGrid, t} : GridPoint{kGrid - t, t};
        case 2:
            return quad ? GridPoint{kGrid - t, kGrid} : GridPoint{0, kGrid - t};
        default:
            return {0, kGrid - t};
    }
}

// The same position measured from the mesh edge's lower vertex index, and back (an involution).
std::int64_t canonical(const PatchTopology& t, int k, std::int64_t pos) {
    return t.forward[k] ? pos : kGrid - pos;
}

// The patch edge a grid point lies on, or -1 inside the patch.
int edge_of_point(bool quad, GridPoint p) {
    if (p.v == 0) return 0;
    if (quad) {
        if (p.u == kGrid) return 1;
        if (p.v == kGrid) return 2;
        if (p.u == 0) return 3;
    } else {
        if (p.u + p.v == kGrid) return 1;
        if (p.u == 0) return 2;
    }
    return -1;
}

// Supporting lines: u = c (dir 0, position v), v = c (dir 1, position u), u + v = c (dir 2,
// position v). The patch edge the line runs along, or -1 for lines through the interior.
int edge_of_line(bool quad, int dir, std::int64_t c) {
    if (dir == 1 && c == 0) return 0;
    if (dir == 0 && c == 0) return quad ? 3 : 2;
    if (quad && dir == 0 && c == kGrid) return 1;
    if (quad && dir == 1 && c == kGrid) return 2;
    if (!quad && dir == 2 && c == kGrid) return 1;
    return -1;
}

struct LineRef {
    int dir = 0;
    std::int64_t c = 0;
    int patch_edge = -1;  // the patch edge the line runs along, or -1 inside the patch
};

LineRef line_of(const PatchTopology& t, GridPoint a, GridPoint b) {
    LineRef l;
    if (a.u == b.u) {
        l.dir = 0, l.c = a.u;
    } else if (a.v == b.v) {
        l.dir = 1, l.c = a.v;
    } else {
        l.dir = 2, l.c = a.u + a.v;
    }
    l.patch_edge = edge_of_line(t.quad(), l.dir, l.c);
    return l;
}

std::int64_t position_on(const LineRef& l, const PatchTopology& t, GridPoint p) {
    if (l.patch_edge >= 0) {
        return canonical(t, l.patch_edge, along_edge(t.quad(), l.patch_edge, p));
    }
    return l.dir == 1 ? p.u : p.v;
}

GridPoint point_at(const LineRef& l, const PatchTopology& t, std::int64_t pos) {
    if (l.patch_edge >= 0) {
        return on_edge(t.quad(), l.patch_edge, canonical(t, l.patch_edge, pos));
    }
    if (l.dir == 0) return {l.c, pos};
    if (l.dir == 1) return {pos, l.c};
    return {l.c - pos, pos};
}

constexpr std::uint32_t kNone = ~std::uint32_t(0);

void sort_unique(std::vector<std::uint64_t>& keys) {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

// Sorted distinct 64-bit keys, each with the output vertex it became (kNone until first used).
// Flat arrays instead of hash maps: on the 10^6-patch office the maps held 400 MB at the
// output's peak, these a few MB.
struct KeyedVertices {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> vertex;

    void seal() {
        sort_unique(keys);
        vertex.assign(keys.size(), kNone);
    }
    void clear() {
        keys.clear();
        vertex.clear();
    }
    std::uint32_t& at(std::uint64_t key) {
        const auto it = std::lower_bound(keys.begin(), keys.end(), key);
        if (it == keys.end() || *it != key) {
            throw std::logic_error("conforming polygons: a leaf corner is missing from its index");
        }
        return vertex[it - keys.begin()];
    }
};

// A point strictly inside mesh edge `edge`, at canonical position `pos` (< 2^25).
std::uint64_t edge_point_key(std::uint32_t edge, std::int64_t pos) {
    return (std::uint64_t(edge) << 25) | std::uint64_t(pos);
}

std::uint64_t interior_point_key(GridPoint p) { return (std::uint64_t(p.u) << 32) | p.v; }

// A position on an interior line of the current patch.
std::uint64_t line_point_key(const LineRef& l, std::int64_t pos) {
    return (std::uint64_t(l.dir) << 52) | (std::uint64_t(l.c) << 26) | std::uint64_t(pos);
}

struct Leaf {
    std::array<GridPoint, 4> corner;
    int count = 0;
};

Leaf leaf_corners(const Element& e, bool quad) {
    Leaf leaf;
    leaf.count = quad ? 4 : 3;
    const auto uv = e.domain.corners(quad);
    for (int k = 0; k < leaf.count; ++k) {
        leaf.corner[k] = {std::llround(uv[k].x() * kGrid), std::llround(uv[k].y() * kGrid)};
    }
    return leaf;
}

// Mesh-edge points are shared by the two patches of the edge, so they are collected for the
// whole mesh first; interior lines and points belong to one patch and are built patch by patch,
// in the output's leaf order, so vertex numbers follow first use as before.
class Builder {
public:
    Builder(const Hierarchy& h, const FaceEdges& edges, std::uint8_t side)
        : m_h(h),
          m_side(side),
          m_topo(h.patch_set(), edges),
          m_mesh_vertex(m_topo.vertex_count(), kNone) {}

    ConformingPolygons build() {
        m_h.for_each_leaf_of(m_side, [&](const Element& e) { collect_edge_points(e); });
        m_edge_points.seal();
        if (m_side == kFront) {
            m_out.offsets.reserve(m_h.leaf_count() + 1);
            m_out.polygon_vertices.reserve(4 * m_h.leaf_count());
        }
        m_h.for_each_leaf_of(m_side, [&](const Element& e) {
            if (!m_patch_leaves.empty() && m_patch_leaves.front()->id.patch != e.id.patch) {
                emit_patch();
            }
            m_patch_leaves.push_back(&e);
        });
        emit_patch();
        m_out.vertices.shrink_to_fit();  // kept through the output stage's peak
        return std::move(m_out);
    }

private:
    // Every leaf corner strictly inside a mesh edge. Such a corner is also an end of a leaf
    // edge along the mesh edge, since the leaves tile the patch, so these are the points that
    // leaf edges on the mesh edge must list.
    void collect_edge_points(const Element& e) {
        const PatchTopology t = m_topo[e.id.patch];
        const Leaf leaf = leaf_corners(e, t.quad());
        for (int k = 0; k < leaf.count; ++k) {
            const int edge = edge_of_point(t.quad(), leaf.corner[k]);
            if (edge < 0) continue;
            const std::int64_t pos = along_edge(t.quad(), edge, leaf.corner[k]);
            if (pos == 0 || pos == kGrid) continue;
            m_edge_points.keys.push_back(edge_point_key(t.edge[edge], canonical(t, edge, pos)));
        }
    }

    void emit_patch() {
        if (m_patch_leaves.empty()) return;  // a hierarchy without patches
        const std::uint32_t patch = m_patch_leaves.front()->id.patch;
        const PatchTopology t = m_topo[patch];
        m_interior_points.clear();
        m_line_points.clear();
        for (const Element* e : m_patch_leaves) {
            const Leaf leaf = leaf_corners(*e, t.quad());
            for (int k = 0; k < leaf.count; ++k) {
                const GridPoint a = leaf.corner[k], b = leaf.corner[(k + 1) % leaf.count];
                if (edge_of_point(t.quad(), a) < 0) {
                    m_interior_points.keys.push_back(interior_point_key(a));
                }
                const LineRef l = line_of(t, a, b);
                if (l.patch_edge >= 0) continue;
                m_line_points.push_back(line_point_key(l, position_on(l, t, a)));
                m_line_points.push_back(line_point_key(l, position_on(l, t, b)));
            }
        }
        m_interior_points.seal();
        sort_unique(m_line_points);
        for (const Element* e : m_patch_leaves) emit_polygon(*e);
        m_patch_leaves.clear();
    }

    // Each leaf edge with the corners strictly inside it, in order from a to b.
    void emit_polygon(const Element& e) {
        const auto start = std::ptrdiff_t(m_out.polygon_vertices.size());
        const PatchTopology t = m_topo[e.id.patch];
        const Leaf leaf = leaf_corners(e, t.quad());
        for (int k = 0; k < leaf.count; ++k) {
            const GridPoint a = leaf.corner[k], b = leaf.corner[(k + 1) % leaf.count];
            emit_vertex(e.id.patch, a);
            const LineRef l = line_of(t, a, b);
            const std::int64_t pa = position_on(l, t, a), pb = position_on(l, t, b);
            const auto key = [&](std::int64_t pos) {
                return l.patch_edge >= 0 ? edge_point_key(t.edge[l.patch_edge], pos)
                                         : line_point_key(l, pos);
            };
            const auto mask = (std::uint64_t(1) << (l.patch_edge >= 0 ? 25 : 26)) - 1;
            const auto& points = l.patch_edge >= 0 ? m_edge_points.keys : m_line_points;
            auto lo = std::upper_bound(points.begin(), points.end(), key(std::min(pa, pb)));
            auto hi = std::lower_bound(lo, points.end(), key(std::max(pa, pb)));
            if (pa < pb) {
                for (auto it = lo; it != hi; ++it) {
                    emit_vertex(e.id.patch, point_at(l, t, std::int64_t(*it & mask)));
                }
            } else {
                for (auto it = hi; it != lo; --it) {
                    emit_vertex(e.id.patch, point_at(l, t, std::int64_t(it[-1] & mask)));
                }
            }
        }
        if (m_side == kBack) {
            std::reverse(m_out.polygon_vertices.begin() + start, m_out.polygon_vertices.end());
        }
        m_out.offsets.push_back(std::int64_t(m_out.polygon_vertices.size()));
    }

    void emit_vertex(std::uint32_t patch, GridPoint p) {
        const PatchTopology t = m_topo[patch];
        const int k = edge_of_point(t.quad(), p);
        std::uint32_t* slot = nullptr;
        VertexKind kind = VertexKind::patch_interior;
        std::uint32_t id = patch;
        int corner = -1;  // of the patch, for a mesh vertex
        if (k < 0) {
            slot = &m_interior_points.at(interior_point_key(p));
        } else if (const std::int64_t pos = along_edge(t.quad(), k, p); pos == 0 || pos == kGrid) {
            kind = VertexKind::mesh_vertex;
            corner = pos == 0 ? k : (k + 1) % t.corner_count;
            id = t.vertex[corner];
            slot = &m_mesh_vertex[id];
        } else {
            kind = VertexKind::mesh_edge;
            id = t.edge[k];
            slot = &m_edge_points.at(edge_point_key(id, canonical(t, k, pos)));
        }
        if (*slot == kNone) {
            *slot = std::uint32_t(m_out.vertices.size());
            m_out.vertices.push_back(make_vertex(kind, id, patch, corner, p));
        }
        m_out.polygon_vertices.push_back(*slot);
    }

    // A mesh vertex is its patch's corner, the mesh's point itself.
    LatticeVertex make_vertex(VertexKind kind, std::uint32_t id, std::uint32_t patch, int corner,
                              GridPoint p) const {
        const Patch& q = m_h.patch_set().patches[patch];
        if (kind == VertexKind::mesh_vertex) return {kind, id, q.corner[corner]};
        const Vec2 uv(double(p.u) / kGrid, double(p.v) / kGrid);
        return {kind, id, q.point(uv)};
    }

    const Hierarchy& m_h;
    std::uint8_t m_side;
    MeshTopology m_topo;
    std::vector<std::uint32_t> m_mesh_vertex;  // output vertex of each mesh vertex
    KeyedVertices m_edge_points;
    // The current patch: its leaves, interior leaf corners and interior line positions.
    std::vector<const Element*> m_patch_leaves;
    KeyedVertices m_interior_points;
    std::vector<std::uint64_t> m_line_points;
    ConformingPolygons m_out;
};

}  // namespace

ConformingPolygons build_conforming_polygons(const Hierarchy& h, const FaceEdges& edges,
                                             std::uint8_t side) {
    return Builder(h, edges, side).build();
}

}  // namespace hmcr
