#include "viz/conforming_polygons.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

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

std::vector<PatchTopology> patch_topology(const PatchMesh& mesh, const PatchSet& set) {
    if (mesh.n_faces() != set.patches.size()) {
        throw std::invalid_argument("shaded mesh: the mesh has " + std::to_string(mesh.n_faces()) +
                                    " faces but the hierarchy " +
                                    std::to_string(set.patches.size()) + " patches");
    }
    std::vector<PatchTopology> topo(mesh.n_faces());
    for (auto f : mesh.faces()) {
        PatchTopology& t = topo[f.idx()];
        std::array<PatchMesh::VertexHandle, 4> v;
        for (auto vh : mesh.fv_range(f)) {
            if (t.corner_count == 4) break;
            v[t.corner_count++] = vh;
        }
        if (t.corner_count != set.patches[f.idx()].corner_count || mesh.valence(f) > 4) {
            throw std::invalid_argument("shaded mesh: face " + std::to_string(f.idx()) +
                                        " does not match its patch");
        }
        for (int k = 0; k < t.corner_count; ++k) {
            const auto next = v[(k + 1) % t.corner_count];
            t.vertex[k] = v[k].idx();
            t.edge[k] = mesh.edge_handle(mesh.find_halfedge(v[k], next)).idx();
            t.forward[k] = v[k].idx() < next.idx();
        }
    }
    return topo;
}

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
    std::uint64_t key = 0;  // mesh edge lines have the top bit set
    int dir = 0;
    std::int64_t c = 0;
    int patch_edge = -1;
};

LineRef line_of(const PatchTopology& t, std::uint32_t patch, GridPoint a, GridPoint b) {
    LineRef l;
    if (a.u == b.u) {
        l.dir = 0, l.c = a.u;
    } else if (a.v == b.v) {
        l.dir = 1, l.c = a.v;
    } else {
        l.dir = 2, l.c = a.u + a.v;
    }
    l.patch_edge = edge_of_line(t.quad(), l.dir, l.c);
    if (l.patch_edge >= 0) {
        l.key = (std::uint64_t(1) << 63) | t.edge[l.patch_edge];
    } else {
        l.key = (std::uint64_t(patch) << 27) | (std::uint64_t(l.dir) << 25) | std::uint64_t(l.c);
    }
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

struct VertexKey {
    std::uint64_t owner = 0;  // kind in the top bits, then the mesh vertex, edge or patch
    std::uint64_t where = 0;  // position along the edge, or packed grid coordinates
    bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        return std::hash<std::uint64_t>()(k.owner * 0x9E3779B97F4A7C15ull ^ k.where);
    }
};

VertexKey make_key(VertexKind kind, std::uint32_t id, std::uint64_t where) {
    return {(std::uint64_t(kind) << 62) | id, where};
}

VertexKey key_of(const PatchTopology& t, std::uint32_t patch, GridPoint p) {
    const int k = edge_of_point(t.quad(), p);
    if (k < 0) {
        return make_key(VertexKind::patch_interior, patch, (std::uint64_t(p.u) << 32) | p.v);
    }
    const std::int64_t pos = along_edge(t.quad(), k, p);
    if (pos == 0) return make_key(VertexKind::mesh_vertex, t.vertex[k], 0);
    if (pos == kGrid)
        return make_key(VertexKind::mesh_vertex, t.vertex[(k + 1) % t.corner_count], 0);
    return make_key(VertexKind::mesh_edge, t.edge[k], canonical(t, k, pos));
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

class Builder {
  public:
    Builder(const Hierarchy& h, const PatchMesh& mesh)
        : m_h(h), m_mesh(mesh), m_topo(patch_topology(mesh, h.patch_set())) {}

    ConformingPolygons build() {
        m_index.reserve(m_h.leaf_count());
        m_h.for_each_leaf([&](const Element& e) { collect_corners(e); });
        for (auto& [key, positions] : m_lines) {
            std::sort(positions.begin(), positions.end());
            positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
        }
        m_out.offsets.reserve(m_h.leaf_count() + 1);
        m_h.for_each_leaf([&](const Element& e) { emit_polygon(e); });
        return std::move(m_out);
    }

  private:
    // Pass 1: every leaf corner onto the supporting lines of the leaf's edges.
    void collect_corners(const Element& e) {
        const PatchTopology& t = m_topo[e.id.patch];
        const Leaf leaf = leaf_corners(e, t.quad());
        for (int k = 0; k < leaf.count; ++k) {
            const GridPoint a = leaf.corner[k], b = leaf.corner[(k + 1) % leaf.count];
            const LineRef l = line_of(t, e.id.patch, a, b);
            auto& positions = m_lines[l.key];
            positions.push_back(position_on(l, t, a));
            positions.push_back(position_on(l, t, b));
        }
    }

    // Pass 2: each leaf edge with the corners strictly inside it, in order from a to b.
    void emit_polygon(const Element& e) {
        const PatchTopology& t = m_topo[e.id.patch];
        const Leaf leaf = leaf_corners(e, t.quad());
        for (int k = 0; k < leaf.count; ++k) {
            const GridPoint a = leaf.corner[k], b = leaf.corner[(k + 1) % leaf.count];
            emit_vertex(e.id.patch, a);
            const LineRef l = line_of(t, e.id.patch, a, b);
            const auto& positions = m_lines.at(l.key);
            const std::int64_t pa = position_on(l, t, a), pb = position_on(l, t, b);
            auto lo = std::upper_bound(positions.begin(), positions.end(), std::min(pa, pb));
            auto hi = std::lower_bound(lo, positions.end(), std::max(pa, pb));
            if (pa < pb) {
                for (auto it = lo; it != hi; ++it) emit_vertex(e.id.patch, point_at(l, t, *it));
            } else {
                for (auto it = hi; it != lo; --it) emit_vertex(e.id.patch, point_at(l, t, it[-1]));
            }
        }
        m_out.offsets.push_back(std::int64_t(m_out.polygon_vertices.size()));
    }

    void emit_vertex(std::uint32_t patch, GridPoint p) {
        const VertexKey key = key_of(m_topo[patch], patch, p);
        auto [it, inserted] = m_index.try_emplace(key, std::uint32_t(m_out.vertices.size()));
        if (inserted) m_out.vertices.push_back(make_vertex(key, patch, p));
        m_out.polygon_vertices.push_back(it->second);
    }

    LatticeVertex make_vertex(const VertexKey& key, std::uint32_t patch, GridPoint p) const {
        const auto kind = VertexKind(key.owner >> 62);
        const auto id = std::uint32_t(key.owner & 0xFFFFFFFFu);
        if (kind == VertexKind::mesh_vertex) {
            const auto& q = m_mesh.point(PatchMesh::VertexHandle(int(id)));
            return {kind, id, Vec3(q[0], q[1], q[2])};
        }
        const Vec2 uv(double(p.u) / kGrid, double(p.v) / kGrid);
        return {kind, id, m_h.patch_set().patches[patch].point(uv)};
    }

    const Hierarchy& m_h;
    const PatchMesh& m_mesh;
    std::vector<PatchTopology> m_topo;
    std::unordered_map<std::uint64_t, std::vector<std::int64_t>> m_lines;
    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> m_index;
    ConformingPolygons m_out;
};

}  // namespace

ConformingPolygons build_conforming_polygons(const Hierarchy& h, const PatchMesh& mesh) {
    return Builder(h, mesh).build();
}

}  // namespace hmcr
