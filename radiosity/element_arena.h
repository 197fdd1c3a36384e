// SPDX-License-Identifier: Apache-2.0
// Storage for lazily created elements: blocks of 4 children that never move once handed out.
// One arena per thread, so creating elements during parallel shooting takes no lock.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "radiosity/element.h"

namespace hmcr {

class ElementArena {
public:
    // Four default-constructed, consecutive elements.
    Element* allocate_block();
    // A block that lost the race to become some element's children; reused next time.
    void give_back(Element* block) { m_spare = block; }
    std::size_t bytes() const { return m_chunks.size() * kChunkBlocks * 4 * sizeof(Element); }

private:
    static constexpr std::size_t kChunkBlocks = 1024;
    std::vector<std::unique_ptr<Element[]>> m_chunks;
    std::size_t m_used = kChunkBlocks;  // blocks used in the last chunk
    Element* m_spare = nullptr;
};

}  // namespace hmcr
