// SPDX-License-Identifier: Apache-2.0
// The link cache of docs/design.md §4.3: the geometric factor of a line-based oracle depends only
// on the element pair and its lines (drawn from the pair's own random stream), so it is
// computed once per (receiver, source) pair and reused by every later ray.
//
// A fixed-size, 2-way set-associative table, one cache line per set: bounded memory. Each set
// is a seqlock: lookups only read (the top-level pairs are looked up by every ray on every
// core, and a lock written on each lookup would bounce their cache lines between cores), an
// insert takes the set by making its version odd. In front of it, each thread keeps a small
// direct-mapped table of the pairs it used last (the top-level pairs of every descent), which
// stays in its own L2 cache. An evicted pair is recomputed to the same value (its stream is
// keyed by the pair), so eviction changes timings, never results.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "radiosity/element.h"

namespace hmcr {

class LinkCache {
public:
    explicit LinkCache(std::size_t max_bytes);
    ~LinkCache();
    LinkCache(const LinkCache&) = delete;
    LinkCache& operator=(const LinkCache&) = delete;

    std::optional<double> find(const Element* receiver, const Element* source) const;
    void insert(const Element* receiver, const Element* source, double factor);
    // Starts loading the pair's set into the CPU cache, for a find() that will come soon.
    void prefetch(const Element* receiver, const Element* source) const;

    std::size_t capacity() const { return m_set_count * kWays; }  // pairs
    std::size_t bytes() const { return m_set_count * sizeof(Set); }
    std::size_t evictions() const { return m_evictions.load(std::memory_order_relaxed); }

private:
    static constexpr int kWays = 2;
    // Atomic fields read with relaxed loads: plain moves, but no data race with a writer.
    struct Entry {
        std::atomic<const Element*> receiver{nullptr};
        std::atomic<const Element*> source{nullptr};
        std::atomic<double> factor{0};
    };
    struct alignas(64) Set {
        std::atomic<std::uint32_t> version{0};  // odd while an insert writes the set
        std::uint32_t next_victim = 0;          // written under the odd version only
        Entry entries[kWays];
    };

    std::uint64_t hash(const Element* receiver, const Element* source) const;
    std::optional<double> find_shared(const Set& s, const Element* receiver,
                                      const Element* source) const;

    struct FreeSets {
        std::size_t count;
        void operator()(Set* sets) const;
    };

    std::uint64_t m_generation;   // tells this cache's entries in the per-thread tables apart
    std::size_t m_set_count = 0;  // a power of two
    std::unique_ptr<Set[], FreeSets> m_sets;
    std::atomic<std::size_t> m_evictions{0};
};

}  // namespace hmcr
