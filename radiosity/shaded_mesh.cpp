// SPDX-License-Identifier: Apache-2.0
#include "radiosity/shaded_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "radiosity/conforming_polygons.h"
#include "radiosity/polynomial_mesh.h"

namespace hmcr {
namespace {

// One use of a lattice vertex by a cell: the slot of the cell's polygon that names it.
struct Incidence {
    std::uint32_t cell = 0;
    std::uint32_t slot = 0;
};

// The incidences grouped by vertex: those of vertex v are inc[first[v] .. first[v + 1]), in
// slot order, which is also patch order (cells are in patch order). A counting sort: at 10^6
// patches there are 4 x 10^6 incidences, the largest block of the output stage, and 8 bytes
// each here instead of a sorted array of 16.
struct VertexIncidences {
    std::vector<std::uint32_t> first;
    std::vector<Incidence> inc;
};

VertexIncidences incidences(const ConformingPolygons& polys) {
    if (polys.polygon_vertices.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("more than 2^32 polygon corners in one solution");
    }
    VertexIncidences v;
    v.first.assign(polys.vertices.size() + 1, 0);
    for (std::uint32_t vertex : polys.polygon_vertices) ++v.first[vertex + 1];
    std::partial_sum(v.first.begin(), v.first.end(), v.first.begin());
    std::vector<std::uint32_t> next(v.first.begin(), v.first.end() - 1);
    v.inc.resize(polys.polygon_vertices.size());
    for (std::size_t c = 0; c + 1 < polys.offsets.size(); ++c) {
        for (auto s = polys.offsets[c]; s < polys.offsets[c + 1]; ++s) {
            v.inc[next[polys.polygon_vertices[s]]++] = {std::uint32_t(c), std::uint32_t(s)};
        }
    }
    return v;
}

// Groups the patches meeting at a vertex into blend groups: two patches blend when they share a
// mesh edge through the vertex, their normals differ by less than the crease angle, and they
// have the same material (and transitively, so a smooth fan around a vertex is one group).
// Radiosity B = E + rho H jumps where E or rho jumps, even where H is smooth: blending there
// would smear a light's edge into the ceiling around it, or one colour into the next.
class CreaseGrouping {
public:
    // Whether the faces across each mesh edge blend is decided once per edge: the grouping runs
    // twice at every vertex that patches share (to count the points, then to emit them), and
    // asks about each edge from both of its ends. Deciding it there, from two patches anywhere
    // in the patch array, was the largest part of the output stage at 10^6 patches. The faces'
    // vertices and edges are kept (32 bytes a face), so the tree can go.
    CreaseGrouping(const Hierarchy& h, FaceEdges edges, double crease_degrees, std::uint8_t side)
        : m_vertices(h.patch_set().vertices),
          m_edges(std::move(edges)),
          m_blends(m_edges.edge_count, 0) {
        const double cos_crease = std::cos(crease_degrees * std::numbers::pi / 180.0);
        const PatchSet& set = h.patch_set();
        constexpr std::uint32_t kNoFace = ~std::uint32_t(0);
        std::vector<std::uint32_t> first_face(m_edges.edge_count, kNoFace);
        for (std::uint32_t f = 0; f < m_edges.faces.size(); ++f) {
            for (int k = 0; k < m_vertices.corner_count(f); ++k) {
                const std::uint32_t e = m_edges.faces[f][k];
                if (first_face[e] == kNoFace) {
                    first_face[e] = f;
                    continue;
                }
                const std::uint32_t f0 = first_face[e];
                if (side == kBack && !(set.two_sided(f0) && set.two_sided(f))) continue;
                const PatchMaterial &m0 = set.material(f0, side), &m1 = set.material(f, side);
                const bool same_material =
                    (m0.reflectance == m1.reflectance).all() && (m0.emission == m1.emission).all();
                m_blends[e] =
                    same_material && set.patches[f0].normal.dot(set.patches[f].normal) > cos_crease;
            }
        }
    }

    // `group` gets each patch's group: the index of one patch of the group.
    void groups(const LatticeVertex& v, const std::vector<std::uint32_t>& patches,
                std::vector<int>& group) {
        m_parent.resize(patches.size());
        std::iota(m_parent.begin(), m_parent.end(), 0);
        if (patches.size() > 1 && v.kind != VertexKind::patch_interior) {
            join_across_sides(v, patches);
        }
        group.resize(patches.size());
        for (std::size_t i = 0; i < patches.size(); ++i) group[i] = find(int(i));
    }

private:
    // Two of the patches join when they have a side on the same blending mesh edge through v
    // (a mesh edge, or an edge with v at one end).
    void join_across_sides(const LatticeVertex& v, const std::vector<std::uint32_t>& patches) {
        m_sides.clear();
        for (std::size_t i = 0; i < patches.size(); ++i) {
            const auto& fv = m_vertices.faces[patches[i]];
            const auto& fe = m_edges.faces[patches[i]];
            const int n = m_vertices.corner_count(patches[i]);
            for (int k = 0; k < n; ++k) {
                const bool through_v = v.kind == VertexKind::mesh_edge
                                           ? fe[k] == v.id
                                           : fv[k] == v.id || fv[(k + 1) % n] == v.id;
                if (through_v && m_blends[fe[k]]) m_sides.emplace_back(fe[k], int(i));
            }
        }
        std::sort(m_sides.begin(), m_sides.end());
        for (std::size_t j = 1; j < m_sides.size(); ++j) {
            if (m_sides[j].first == m_sides[j - 1].first) {
                m_parent[find(m_sides[j - 1].second)] = find(m_sides[j].second);
            }
        }
    }
    int find(int i) {
        while (m_parent[i] != i) i = m_parent[i] = m_parent[m_parent[i]];
        return i;
    }

    FaceVertices m_vertices;
    FaceEdges m_edges;
    std::vector<std::uint8_t> m_blends;  // by mesh edge: its two faces blend
    std::vector<int> m_parent;
    std::vector<std::pair<std::uint32_t, int>> m_sides;  // (mesh edge, patch) at one vertex
};

void fill_cells(const Hierarchy& h, std::uint8_t side, ShadedMesh& out) {
    if (side == kFront) {
        const std::size_t leaves = h.leaf_count();
        out.element_radiosity.reserve(leaves);
        out.hierarchy_level.reserve(leaves);
        out.patch_id.reserve(leaves);
        out.element_area.reserve(leaves);
        out.side.reserve(leaves);
    }
    h.for_each_leaf_of(side, [&](const Element& e) {
        out.element_radiosity.push_back(e.radiosity);
        out.hierarchy_level.push_back(e.id.depth);
        out.patch_id.push_back(int(e.id.patch));
        out.element_area.push_back(e.area);
        out.side.push_back(side);
    });
}

// Appends a point with the area-weighted average B of the cells of [first, last).
void emit_point(const Incidence* first, const Incidence* last, const Vec3& position,
                ShadedMesh& out) {
    Rgb sum = Rgb::Zero();
    double area = 0;
    for (auto* i = first; i != last; ++i) {
        out.connectivity[i->slot] = std::int64_t(out.points.size());
        sum += out.element_area[i->cell] * out.element_radiosity[i->cell];
        area += out.element_area[i->cell];
    }
    out.points.push_back(position);
    out.point_radiosity.push_back(area > 0 ? Rgb(sum / area) : Rgb(Rgb::Zero()));
}

// The patches of the incidences [first, last), each once (incidences are in patch order).
void distinct_patches(const Incidence* first, const Incidence* last, const ShadedMesh& out,
                      std::vector<std::uint32_t>& patches) {
    patches.clear();
    for (auto* i = first; i != last; ++i) {
        const auto patch = std::uint32_t(out.patch_id[i->cell]);
        if (patches.empty() || patches.back() != patch) patches.push_back(patch);
    }
}

// The buffers of one vertex's grouping, kept for all vertices (the output stage's allocations
// were otherwise several per vertex).
struct GroupScratch {
    std::vector<std::uint32_t> patches;
    std::vector<int> group;
    std::vector<std::int64_t> point_of_group;
    std::vector<Rgb> sum;
    std::vector<double> area;
};

// The incidences [first, last) share one lattice vertex: one output point per blend group,
// holding the area-weighted average B of the group's leaves around the vertex.
void emit_points(const Incidence* first, const Incidence* last, const LatticeVertex& v,
                 CreaseGrouping& grouping, GroupScratch& g, ShadedMesh& out) {
    distinct_patches(first, last, out, g.patches);
    grouping.groups(v, g.patches, g.group);
    g.point_of_group.assign(g.patches.size(), -1);
    g.sum.assign(g.patches.size(), Rgb::Zero());
    g.area.assign(g.patches.size(), 0.0);
    std::size_t p = 0;
    for (auto* i = first; i != last; ++i) {
        while (g.patches[p] != std::uint32_t(out.patch_id[i->cell])) ++p;
        const int k = g.group[p];
        if (g.point_of_group[k] < 0) {
            g.point_of_group[k] = std::int64_t(out.points.size());
            out.points.push_back(v.position);
        }
        out.connectivity[i->slot] = g.point_of_group[k];
        g.sum[k] += out.element_area[i->cell] * out.element_radiosity[i->cell];
        g.area[k] += out.element_area[i->cell];
    }
    out.point_radiosity.resize(out.points.size(), Rgb::Zero());
    for (std::size_t k = 0; k < g.patches.size(); ++k) {
        if (g.point_of_group[k] >= 0 && g.area[k] > 0) {
            out.point_radiosity[g.point_of_group[k]] = g.sum[k] / g.area[k];
        }
    }
}

// What the shading takes from the tree: the conforming polygons, the cells' data and which
// faces blend across each mesh edge. The rest needs only these.
struct FromTree {
    ConformingPolygons polys;
    ShadedMesh out;
    CreaseGrouping grouping;
};

FromTree take_from_tree(const Hierarchy& h, FaceEdges edges, double crease_degrees,
                        std::uint8_t side) {
    ConformingPolygons polys = build_conforming_polygons(h, edges, side);
    FromTree t{std::move(polys), {}, CreaseGrouping(h, std::move(edges), crease_degrees, side)};
    fill_cells(h, side, t.out);
    return t;
}

// The fronts, and the backs if any exist: each side's own shading, taken from the tree.
std::vector<FromTree> take_sides(const Hierarchy& h, double crease_degrees) {
    FaceEdges edges = face_edges(h.patch_set().vertices);
    std::vector<FromTree> sides;
    if (h.has_backs()) sides.push_back(take_from_tree(h, edges, crease_degrees, kBack));
    sides.insert(sides.begin(), take_from_tree(h, std::move(edges), crease_degrees, kFront));
    return sides;
}

ShadedMesh finish(FromTree t) {
    ConformingPolygons& polys = t.polys;
    ShadedMesh& out = t.out;
    CreaseGrouping& grouping = t.grouping;
    out.connectivity.assign(polys.polygon_vertices.size(), -1);
    const VertexIncidences vi = incidences(polys);
    out.offsets = std::move(polys.offsets);
    polys.polygon_vertices = {};  // in `vi` now
    auto for_each_vertex = [&](auto&& one_patch, auto&& several) {
        for (std::size_t v = 0; v < polys.vertices.size(); ++v) {
            const Incidence* first = vi.inc.data() + vi.first[v];
            const Incidence* last = vi.inc.data() + vi.first[v + 1];
            if (first == last) continue;
            if (out.patch_id[first->cell] == out.patch_id[last[-1].cell]) {  // the common case
                one_patch(first, last, polys.vertices[v]);
            } else {
                several(first, last, polys.vertices[v]);
            }
        }
    };
    // The points are counted first: grown past a reserve, the two point arrays kept twice the
    // room (2.24 M points' room for 1.35 M on the 10^6-patch office: 70 MB more at the peak of
    // the output, the largest of the whole solve).
    std::size_t points = 0;
    GroupScratch scratch;
    for_each_vertex([&](auto, auto, const LatticeVertex&) { ++points; },
                    [&](const Incidence* first, const Incidence* last, const LatticeVertex& v) {
                        distinct_patches(first, last, out, scratch.patches);
                        grouping.groups(v, scratch.patches, scratch.group);
                        for (std::size_t k = 0; k < scratch.group.size(); ++k) {
                            points += scratch.group[k] == int(k);
                        }
                    });
    out.points.reserve(points);
    out.point_radiosity.reserve(points);
    for_each_vertex([&](const Incidence* first, const Incidence* last,
                        const LatticeVertex& v) { emit_point(first, last, v.position, out); },
                    [&](const Incidence* first, const Incidence* last, const LatticeVertex& v) {
                        emit_points(first, last, v, grouping, scratch, out);
                    });
    return std::move(out);
}

// The backs' cells and points after the fronts'.
void append(ShadedMesh& out, ShadedMesh back) {
    const auto points = std::int64_t(out.points.size());
    const auto corners = std::int64_t(out.connectivity.size());
    out.points.insert(out.points.end(), back.points.begin(), back.points.end());
    out.point_radiosity.insert(out.point_radiosity.end(), back.point_radiosity.begin(),
                               back.point_radiosity.end());
    for (std::size_t c = 1; c < back.offsets.size(); ++c) {
        out.offsets.push_back(corners + back.offsets[c]);
    }
    for (const std::int64_t v : back.connectivity) out.connectivity.push_back(points + v);
    const auto extend = [](auto& to, const auto& from) {
        to.insert(to.end(), from.begin(), from.end());
    };
    extend(out.element_radiosity, back.element_radiosity);
    extend(out.hierarchy_level, back.hierarchy_level);
    extend(out.patch_id, back.patch_id);
    extend(out.element_area, back.element_area);
    extend(out.side, back.side);
}

ShadedMesh finish_sides(std::vector<FromTree> sides) {
    ShadedMesh out = finish(std::move(sides.front()));
    if (sides.size() > 1) append(out, finish(std::move(sides.back())));
    return out;
}

}  // namespace

ShadedMesh build_shaded_mesh(const Hierarchy& h, double crease_degrees) {
    if (h.basis() != Basis::constant) return build_polynomial_mesh(h);
    return finish_sides(take_sides(h, crease_degrees));
}

ShadedMesh build_shaded_mesh(std::unique_ptr<Hierarchy> h, double crease_degrees) {
    if (h->basis() != Basis::constant) return build_polynomial_mesh(*h);
    std::vector<FromTree> taken = take_sides(*h, crease_degrees);
    h.reset();
    return finish_sides(std::move(taken));
}

void set_cluster_ids(ShadedMesh& mesh, std::span<const std::int32_t> cluster_of_side) {
    mesh.cluster_id.clear();
    if (cluster_of_side.empty()) return;
    mesh.cluster_id.resize(mesh.cell_count());
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
        mesh.cluster_id[c] = cluster_of_side[2 * std::size_t(mesh.patch_id[c]) + mesh.side[c]];
    }
}

}  // namespace hmcr
