// SPDX-License-Identifier: Apache-2.0
#include "radiosity/leaf_index.h"

#include <stdexcept>

namespace hmcr {

LeafIndex::LeafIndex(Hierarchy& h) : m_h(h) {
    const std::size_t patches = h.patch_count();
    const bool backs = !h.patch_set().back_materials.empty();
    for (std::uint8_t side : {kFront, kBack}) {
        if (side == kBack && !backs) break;
        std::vector<std::uint32_t>& roots = m_roots[side];
        roots.assign(patches, kUnsplit);
        for (std::size_t p = 0; p < patches; ++p) {
            if (side == kBack && !h.back_root(p)) continue;  // asking root() would make it
            Element& root = h.root(p, side);
            if (root.is_leaf()) continue;
            const std::size_t leaves = m_leaves.size();
            const std::uint32_t node = add(root);
            roots[p] = h.patch_set().patches[p].is_quad()
                           ? kQuad | add_grid(node, m_leaves.size() - leaves)
                           : node;
        }
    }
}

// Depth first, so that a subtree's nodes are near one another.
std::uint32_t LeafIndex::add(Element& e) {
    Element* c = e.children();
    if (!c) {
        if (m_leaves.size() >= kLeaf) throw std::length_error("too many leaves to index");
        m_leaves.push_back(&e);
        return kLeaf | std::uint32_t(m_leaves.size() - 1);
    }
    if (m_nodes.size() >= kQuad) throw std::length_error("too many split elements to index");
    const auto node = std::uint32_t(m_nodes.size());
    m_nodes.emplace_back();
    for (int k = 0; k < 4; ++k) {
        const std::uint32_t entry = add(c[k]);
        m_nodes[node][k] = entry;
    }
    return node;
}

// The grid of the quad whose root is node `root`, at the deepest depth with no more cells
// than the quad has leaves (at least 1, as a split quad has 4): at most 4 bytes a leaf.
std::uint32_t LeafIndex::add_grid(std::uint32_t root, std::size_t leaves) {
    int depth = 1;
    while (std::size_t(4) << (2 * depth) <= leaves) ++depth;
    const std::uint32_t n = 1u << depth;
    if (m_cells.size() + std::size_t(n) * n >= kLeaf || m_grids.size() >= kQuad) {
        throw std::length_error("too many leaves to index");
    }
    const auto grid = std::uint32_t(m_grids.size());
    m_grids.push_back({std::uint32_t(m_cells.size()), depth});
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            std::uint32_t entry = root;
            for (int l = depth - 1; l >= 0 && !(entry & kLeaf); --l) {
                entry = m_nodes[entry][Domain::quad_cell_child(i, j, l)];
            }
            m_cells.push_back(entry);
        }
    }
    return grid;
}

std::uint32_t LeafIndex::entry_at(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const {
    const std::vector<std::uint32_t>& roots = m_roots[side];
    const std::uint32_t root = roots.empty() ? kUnsplit : roots[patch];
    if (root == kUnsplit) return kUnsplit;
    if (!(root & kQuad)) {
        DomainWalk walk(false, uv);
        std::uint32_t entry = root;
        while (!(entry & kLeaf)) entry = m_nodes[entry][walk.step()];
        return entry;
    }
    const Grid& g = m_grids[root & ~kQuad];
    const std::uint32_t i = Domain::quad_cell(uv.x(), g.depth),
                        j = Domain::quad_cell(uv.y(), g.depth);
    std::uint32_t entry = m_cells[g.first + (std::size_t(j) << g.depth) + i];
    if (!(entry & kLeaf)) {
        DomainWalk walk(true, uv, Domain::quad_cell_domain(i, j, g.depth));
        do entry = m_nodes[entry][walk.step()];
        while (!(entry & kLeaf));
    }
    return entry;
}

Element& LeafIndex::locate(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const {
    const std::uint32_t entry = entry_at(patch, side, uv);
    return entry == kUnsplit ? m_h.root(patch, side) : *m_leaves[entry & ~kLeaf];
}

std::size_t LeafIndex::number(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const {
    const std::uint32_t entry = entry_at(patch, side, uv);
    return entry == kUnsplit ? m_leaves.size() + 2 * std::size_t(patch) + side
                             : std::size_t(entry & ~kLeaf);
}

std::size_t LeafIndex::numbers() const { return m_leaves.size() + 2 * m_h.patch_count(); }

}  // namespace hmcr
