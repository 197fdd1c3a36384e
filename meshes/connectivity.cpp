// SPDX-License-Identifier: Apache-2.0
#include "meshes/connectivity.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace hmcr {

FaceVertices face_vertices(const PatchMesh& mesh) {
    FaceVertices out;
    out.vertex_count = std::uint32_t(mesh.n_vertices());
    out.faces.reserve(mesh.n_faces());
    for (auto f : mesh.faces()) {
        if (mesh.valence(f) < 3 || mesh.valence(f) > 4) {
            throw std::invalid_argument("face " + std::to_string(f.idx()) +
                                        " is not a triangle or a quad");
        }
        std::array<std::uint32_t, 4> v{kNoCorner, kNoCorner, kNoCorner, kNoCorner};
        int n = 0;
        for (auto fv : mesh.fv_range(f)) v[n++] = std::uint32_t(fv.idx());
        out.faces.push_back(v);
    }
    return out;
}

// The sides are grouped by their lower vertex (a counting sort), then by their upper vertex
// and position within each group: the sides of one edge end up next to each other, the first
// appearance first. Hash maps would cost a node per edge (4 M at 10^6 patches).
FaceEdges face_edges(const FaceVertices& vertices) {
    const std::size_t sides = 4 * vertices.faces.size();
    if (sides >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("more than 2^32 face sides in one mesh");
    }
    auto ends = [&](std::size_t side) {
        const auto& f = vertices.faces[side / 4];
        const int n = vertices.corner_count(side / 4), k = int(side % 4);
        return std::pair(f[k], f[(k + 1) % n]);
    };
    auto is_side = [&](std::size_t side) {
        return side % 4 != 3 || vertices.faces[side / 4][3] != kNoCorner;
    };
    std::vector<std::uint32_t> first(std::size_t(vertices.vertex_count) + 1, 0);
    for (std::size_t s = 0; s < sides; ++s) {
        if (!is_side(s)) continue;
        const auto [a, b] = ends(s);
        ++first[std::min(a, b) + 1];
    }
    std::partial_sum(first.begin(), first.end(), first.begin());
    // (upper vertex, side) of each side, grouped by lower vertex.
    std::vector<std::uint64_t> by_lower(first.back());
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t s = 0; s < sides; ++s) {
        if (!is_side(s)) continue;
        const auto [a, b] = ends(s);
        by_lower[next[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | s;
    }
    next = {};
    // Each side first names the first side of its edge, then that side's edge number.
    FaceEdges out;
    out.faces.assign(vertices.faces.size(), {kNoCorner, kNoCorner, kNoCorner, kNoCorner});
    std::uint32_t* side_edge = out.faces.empty() ? nullptr : out.faces[0].data();
    for (std::size_t v = 0; v + 1 < first.size(); ++v) {
        auto* lo = by_lower.data() + first[v];
        auto* hi = by_lower.data() + first[v + 1];
        std::sort(lo, hi);
        for (auto* i = lo; i != hi; ++i) {
            const bool same_edge = i != lo && (i[-1] >> 32) == (*i >> 32);
            side_edge[std::uint32_t(*i)] =
                same_edge ? side_edge[std::uint32_t(i[-1])] : std::uint32_t(*i);
        }
    }
    for (std::size_t s = 0; s < sides; ++s) {
        if (!is_side(s)) continue;
        const std::uint32_t first_side = side_edge[s];
        side_edge[s] = first_side == s ? out.edge_count++ : side_edge[first_side];
    }
    return out;
}

}  // namespace hmcr
