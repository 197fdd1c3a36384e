// SPDX-License-Identifier: Apache-2.0
// The rays of an iteration dealt to its sources in proportion to their weights, by systematic
// sampling (docs/design.md §3.1): with N rays, cumulative weights W_l and total S, source l
// shoots the rays [floor(N W_l / S + o), floor(N W_(l+1) / S + o)) for one uniform offset o.
// Each source gets N w_l / S rays in expectation, as with an alias pick a ray, but the counts
// vary by at most one, and a source's rays are consecutive: one region's rays start together.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace hmcr {

class RayStrata {
public:
    // The rays first .. first + rays - 1 over `weights` (not all zero, none negative), shifted
    // by `offset` in [0, 1).
    void assign(std::span<const double> weights, std::uint64_t rays, double offset,
                std::uint64_t first = 0);

    // The source that shoots ray `ray` (one of the rays assigned).
    std::uint32_t source_of(std::uint64_t ray) const;
    // The first ray of `source`: ray r is its (r - first_ray(source))th.
    std::uint64_t first_ray(std::uint32_t source) const { return m_start[source]; }
    std::size_t sources() const { return m_start.empty() ? 0 : m_start.size() - 1; }
    std::uint64_t first() const { return m_first; }

    // Which points of which sequence a source's rays are (rays/sobol.h). As assigned, source l's
    // rays are points 0, 1, ... of sequence l + first(), scrambled by the iteration's key.
    // continue_sequences(key), then continue_source for every source, makes them the points
    // from first_point(l) on of a sequence the source keeps through the iterations (a fixed
    // mesh's leaves, docs/design.md §3.2), all scrambled by `key`; the next assign undoes it.
    void continue_sequences(std::uint64_t key);
    void continue_source(std::uint32_t source, std::uint64_t sequence, std::uint64_t first_point) {
        m_sequence[source] = sequence;
        m_first_point[source] = first_point;
    }
    bool continued() const { return m_continued; }
    std::uint64_t sequence(std::uint32_t source) const {
        return continued() ? m_sequence[source] : source + m_first;
    }
    std::uint64_t first_point(std::uint32_t source) const {
        return continued() ? m_first_point[source] : 0;
    }
    // The key of the scrambles: the iteration's, unless the sequences continue.
    std::uint64_t scramble_key(std::uint64_t iteration_key) const {
        return continued() ? m_key : iteration_key;
    }

private:
    std::vector<std::uint64_t> m_start;  // one a source, and the end of the rays last
    std::uint64_t m_first = 0;
    bool m_continued = false;
    std::uint64_t m_key = 0;
    std::vector<std::uint64_t> m_sequence, m_first_point;  // one a source when continued
};

}  // namespace hmcr
