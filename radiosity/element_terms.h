// SPDX-License-Identifier: Apache-2.0
// The coefficients beyond the first of a higher-order element's radiosity (docs/design.md §3.14):
// coefficient 0 of B, Delta B and the received power is the Element's own (the mean, which every
// oracle, the pull and the convergence test read), and coefficients 1 .. K-1 of its basis
// (basis.h) are kept here, K - 1 slots per element. They live apart from the elements so that a
// constant solve's elements stay as they are; an element names its first slot by index.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "common/types.h"
#include "radiosity/basis.h"
#include "radiosity/power_quanta.h"

namespace hmcr {

// One coefficient of an element's B and Delta B, and what the current iteration deposited
// toward it, in whole quanta of the iteration's term quantum (shooting.h).
struct TermSlot {
    Rgb radiosity = Rgb::Zero();
    Rgb unshot = Rgb::Zero();
    Quanta received{};
};

// Slots handed out in runs of consecutive ones that never move, from any thread without a lock
// but the rare one that adds a chunk. The slots' order depends on the threads' timing; the values
// never do, since nothing reads a slot by its index but the element it was given to.
class TermStore {
public:
    static constexpr std::uint32_t kNone = UINT32_MAX;

    explicit TermStore(int per_element);  // K - 1 slots for each element
    TermStore(const TermStore&) = delete;
    TermStore& operator=(const TermStore&) = delete;
    ~TermStore();

    int per_element() const { return m_per; }
    // The first slot of `elements` consecutive elements' runs, zeroed.
    std::uint32_t allocate(int elements);
    TermSlot* at(std::uint32_t first) const {
        return m_chunks[first >> kChunkBits].load(std::memory_order_acquire) +
               (first & (kChunkSlots - 1));
    }
    std::size_t bytes() const;

private:
    static constexpr int kChunkBits = 16;
    static constexpr std::uint32_t kChunkSlots = 1u << kChunkBits;
    static constexpr std::size_t kChunks = std::size_t(1) << (30 - kChunkBits);  // 2^30 slots

    int m_per;
    std::atomic<std::uint64_t> m_next{0};
    std::unique_ptr<std::atomic<TermSlot*>[]> m_chunks;
    std::mutex m_mutex;  // adds a chunk
    std::atomic<std::size_t> m_chunk_count{0};
};

// An element's coefficients on its basis, one row per function, one column per channel.
using RgbCoefficients = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxBasisSize, 3>;

}  // namespace hmcr
