// SPDX-License-Identifier: Apache-2.0
// The leaves of a fixed mesh by parameter point, for the rays of a frozen pass (docs/design.md
// §3.10). Finding the leaf at a hit walks the side's quadtree from its root; through the
// elements that reads a cache line or two of a different element at every level, which made
// the walk about a fifth of a frozen pass. Here each split element is a node of four 4-byte
// entries in one small array, and the domains are recomputed on the way down (a DomainWalk,
// rays/domain.h), so a walk reads a few nodes and touches only the leaf it finds. A split quad
// starts lower: its cells at a depth where there are about as many cells as leaves are a grid
// indexed by the point's binary digits, each cell holding the leaf over it or the node under
// it, so that a walk is a lookup and the few levels below the grid.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "radiosity/hierarchy.h"

namespace hmcr {

class LeafIndex {
public:
    // The leaves `h` has now. `h` must not be split while the index is used; a side whose root
    // does not exist yet (the back of a two-sided patch no light reached) is its own leaf.
    explicit LeafIndex(Hierarchy& h);

    // The leaf of the side (patch, side) containing uv: the element h.locate(h.root(patch,
    // side), uv) finds.
    Element& locate(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const;
    // The number of the leaf locate finds, below numbers(): one per leaf, the same whether or
    // not the side's root has been made since the index was (each side that is its own leaf
    // has the number of its patch and side), so that it names the leaf through a pass.
    std::size_t number(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const;
    std::size_t numbers() const;

private:
    // An entry is a node's index, or kLeaf plus a leaf's index. A side's root entry says
    // whether the patch is a quad (kQuad, then it is the quad's grid), so that a walk does not
    // read the patch.
    static constexpr std::uint32_t kLeaf = 1u << 31, kQuad = 1u << 30, kUnsplit = ~0u;

    // A split quad's cells at `depth` (Domain::quad_cell), row by row from m_cells[first].
    struct Grid {
        std::uint32_t first = 0;
        int depth = 0;
    };

    // The entry of the leaf at uv: kLeaf plus its index, or kUnsplit for a side that is its
    // own leaf.
    std::uint32_t entry_at(std::uint32_t patch, std::uint8_t side, const Vec2& uv) const;
    std::uint32_t add(Element& e);
    std::uint32_t add_grid(std::uint32_t root, std::size_t leaves);

    Hierarchy& m_h;
    std::vector<std::array<std::uint32_t, 4>> m_nodes;
    std::vector<Element*> m_leaves;
    std::vector<Grid> m_grids;
    std::vector<std::uint32_t> m_cells;  // entries, as a node's
    // Per side (kFront, kBack), per patch: a triangle's root node, a quad's grid with kQuad, or
    // kUnsplit for a root that is a leaf. The back's is empty when no patch is two-sided.
    std::array<std::vector<std::uint32_t>, 2> m_roots;
};

}  // namespace hmcr
