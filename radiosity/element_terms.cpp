// SPDX-License-Identifier: Apache-2.0
#include "radiosity/element_terms.h"

#include <new>
#include <stdexcept>

namespace hmcr {

TermStore::TermStore(int per_element)
    : m_per(per_element), m_chunks(std::make_unique<std::atomic<TermSlot*>[]>(kChunks)) {
    for (std::size_t c = 0; c < kChunks; ++c) m_chunks[c].store(nullptr, std::memory_order_relaxed);
}

TermStore::~TermStore() {
    for (std::size_t c = 0; c < kChunks; ++c) {
        if (TermSlot* chunk = m_chunks[c].load(std::memory_order_relaxed)) {
            ::operator delete(chunk, std::align_val_t(alignof(TermSlot)));
        }
    }
}

std::uint32_t TermStore::allocate(int elements) {
    const std::uint64_t n = std::uint64_t(elements) * std::uint64_t(m_per);
    std::uint64_t start = m_next.load(std::memory_order_relaxed), end = 0;
    do {
        // A run never crosses a chunk's end, so its slots are consecutive in memory.
        std::uint64_t first = start;
        if (first / kChunkSlots != (first + n - 1) / kChunkSlots) {
            first = (first + n - 1) / kChunkSlots * kChunkSlots;
        }
        end = first + n;
        if (end > std::uint64_t(kChunks) * kChunkSlots - 1) {
            throw std::length_error("more than 2^30 coefficient slots");
        }
        if (m_next.compare_exchange_weak(start, end, std::memory_order_relaxed)) {
            start = first;
            break;
        }
    } while (true);
    const std::size_t chunk = start >> kChunkBits;
    if (!m_chunks[chunk].load(std::memory_order_acquire)) {
        const std::lock_guard lock(m_mutex);
        if (!m_chunks[chunk].load(std::memory_order_relaxed)) {
            // Raw memory: a slot is written when it is handed out, so a chunk's pages are
            // touched only as far as it is used.
            m_chunks[chunk].store(
                static_cast<TermSlot*>(::operator new(kChunkSlots * sizeof(TermSlot),
                                                      std::align_val_t(alignof(TermSlot)))),
                std::memory_order_release);
            m_chunk_count.fetch_add(1, std::memory_order_relaxed);
        }
    }
    TermSlot* slots = at(std::uint32_t(start));
    for (std::uint64_t k = 0; k < n; ++k) new (slots + k) TermSlot{};
    return std::uint32_t(start);
}

std::size_t TermStore::bytes() const {
    return m_chunk_count.load() * kChunkSlots * sizeof(TermSlot) +
           kChunks * sizeof(std::atomic<TermSlot*>);
}

}  // namespace hmcr
