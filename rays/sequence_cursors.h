// SPDX-License-Identifier: Apache-2.0
// The Sobol sequences a fixed mesh's sources keep through the iterations of a pass (docs/design.md
// §3.2): a source region's rays in an iteration are the points after the ones its rays took in
// the iterations before, so that over the pass each region's rays are one scrambled
// low-discrepancy sequence rather than one short sequence an iteration. The cursors follow only
// the strata's dealing, which every rank and thread count computes alike.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>

#include "rays/ray_generator.h"
#include "rays/ray_strata.h"

namespace hmcr {

class SequenceCursors {
public:
    // The sequences' scrambles take `key`, which no iteration's stream may take.
    explicit SequenceCursors(std::uint64_t key) : m_key(key) {}

    // Continues `strata`'s sources, the regions `regions` in order, each on its region's sequence
    // from the point after its last ray so far (a region seen first gets the next new sequence),
    // and moves each past the rays the strata deal it.
    void advance(std::span<const RayRegion> regions, RayStrata& strata);

private:
    // A region by its bits: its patch, side and domain.
    struct Region {
        std::uint64_t u0, v0, s;
        std::uint32_t patch;
        std::uint16_t side;
        bool operator==(const Region&) const = default;
    };
    struct RegionHash {
        std::size_t operator()(const Region& r) const;
    };
    struct Cursor {
        std::uint64_t sequence = 0, next_point = 0;
    };

    std::uint64_t m_key;
    std::unordered_map<Region, Cursor, RegionHash> m_cursors;
};

}  // namespace hmcr
