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
            roots[p] = add(root) | (h.patch_set().patches[p].is_quad() ? kQuad : 0);
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

Element& LeafIndex::locate(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const {
    const std::vector<std::uint32_t>& roots = m_roots[side];
    const std::uint32_t root = roots.empty() ? kUnsplit : roots[patch];
    if (root == kUnsplit) return m_h.root(patch, side);
    DomainWalk walk(root & kQuad, uv);
    std::uint32_t entry = root & ~kQuad;
    while (!(entry & kLeaf)) entry = m_nodes[entry][walk.step()];
    return *m_leaves[entry & ~kLeaf];
}

}  // namespace hmcr
