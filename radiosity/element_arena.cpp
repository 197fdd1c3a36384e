// SPDX-License-Identifier: Apache-2.0
#include "radiosity/element_arena.h"

namespace hmcr {

Element* ElementArena::allocate_block() {
    if (m_spare) {
        Element* block = m_spare;
        m_spare = nullptr;
        return block;
    }
    if (m_used == kChunkBlocks) {
        m_chunks.push_back(std::make_unique<Element[]>(kChunkBlocks * 4));
        m_used = 0;
    }
    return &m_chunks.back()[4 * m_used++];
}

}  // namespace hmcr
