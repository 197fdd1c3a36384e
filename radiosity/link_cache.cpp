// SPDX-License-Identifier: Apache-2.0
#include "radiosity/link_cache.h"

#include <immintrin.h>
#include <sys/mman.h>

#include <array>
#include <bit>
#include <cstdlib>
#include <memory>
#include <new>

namespace hmcr {

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;

// The per-thread front table: 4,096 pairs, 128 KiB.
struct FrontEntry {
    const Element* receiver = nullptr;
    const Element* source = nullptr;
    std::uint64_t generation = 0;
    double factor = 0;
};
constexpr std::size_t kFrontSize = 4096;
thread_local std::array<FrontEntry, kFrontSize> t_front;

std::atomic<std::uint64_t> g_generations{0};

// Memory for the sets, in transparent huge pages where the kernel allows: lookups land on
// random sets, and with 4 KiB pages nearly every one would also miss the TLB.
void* allocate_table(std::size_t bytes) {
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (!p) throw std::bad_alloc();
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal changes speed, not results
    return p;
}

}  // namespace

void LinkCache::FreeSets::operator()(Set* sets) const {
    std::destroy_n(sets, count);
    std::free(sets);
}

LinkCache::LinkCache(std::size_t max_bytes)
    : m_generation(++g_generations),
      m_set_count(std::bit_floor(std::max<std::size_t>(1, max_bytes / sizeof(Set)))),
      m_sets(static_cast<Set*>(allocate_table(m_set_count * sizeof(Set))), FreeSets{m_set_count}) {
    std::uninitialized_default_construct_n(m_sets.get(), m_set_count);
}

LinkCache::~LinkCache() = default;

std::uint64_t LinkCache::hash(const Element* receiver, const Element* source) const {
    // Elements are 8-byte aligned; mix both pointers so neighbouring pairs spread out.
    std::uint64_t h = reinterpret_cast<std::uintptr_t>(receiver) * 0x9e3779b97f4a7c15ULL;
    h ^= reinterpret_cast<std::uintptr_t>(source) * 0xc2b2ae3d27d4eb4fULL;
    return h ^ (h >> 29);
}

std::optional<double> LinkCache::find(const Element* receiver, const Element* source) const {
    const std::uint64_t h = hash(receiver, source);
    FrontEntry& front = t_front[(h >> 40) & (kFrontSize - 1)];
    if (front.receiver == receiver && front.source == source && front.generation == m_generation) {
        return front.factor;
    }
    const auto found = find_shared(m_sets[h & (m_set_count - 1)], receiver, source);
    if (found) front = {receiver, source, m_generation, *found};
    return found;
}

void LinkCache::prefetch(const Element* receiver, const Element* source) const {
    const std::uint64_t h = hash(receiver, source);
    _mm_prefetch(reinterpret_cast<const char*>(&m_sets[h & (m_set_count - 1)]), _MM_HINT_T0);
}

std::optional<double> LinkCache::find_shared(const Set& s, const Element* receiver,
                                             const Element* source) const {
    constexpr auto relaxed = std::memory_order_relaxed;
    for (;;) {
        const std::uint32_t before = s.version.load(std::memory_order_acquire);
        if (before & 1) {  // an insert is writing this set
            _mm_pause();
            continue;
        }
        std::optional<double> found;
        for (const Entry& e : s.entries) {
            if (e.receiver.load(relaxed) == receiver && e.source.load(relaxed) == source) {
                found = e.factor.load(relaxed);
            }
        }
        std::atomic_thread_fence(std::memory_order_acquire);
        if (s.version.load(relaxed) == before) return found;  // nothing changed meanwhile
    }
}

void LinkCache::insert(const Element* receiver, const Element* source, double factor) {
    const std::uint64_t h = hash(receiver, source);
    t_front[(h >> 40) & (kFrontSize - 1)] = {receiver, source, m_generation, factor};
    Set& s = m_sets[h & (m_set_count - 1)];
    constexpr auto relaxed = std::memory_order_relaxed;
    std::uint32_t version = s.version.load(relaxed);
    while ((version & 1) ||
           !s.version.compare_exchange_weak(version, version + 1, std::memory_order_acquire)) {
        _mm_pause();
        version = s.version.load(relaxed);
    }
    std::atomic_thread_fence(std::memory_order_release);
    bool present = false;  // another thread may have inserted the pair first
    for (const Entry& e : s.entries) {
        present |= e.receiver.load(relaxed) == receiver && e.source.load(relaxed) == source;
    }
    if (!present) {
        Entry& victim = s.entries[s.next_victim];
        if (victim.receiver.load(relaxed)) m_evictions.fetch_add(1, relaxed);
        victim.receiver.store(receiver, relaxed);
        victim.source.store(source, relaxed);
        victim.factor.store(factor, relaxed);
        s.next_victim = (s.next_victim + 1) % kWays;
    }
    s.version.store(version + 2, std::memory_order_release);
}

}  // namespace hmcr
