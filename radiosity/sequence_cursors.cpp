// SPDX-License-Identifier: Apache-2.0
#include "radiosity/sequence_cursors.h"

#include "rays/domain.h"

namespace hmcr {

SequenceCursors::SequenceCursors(const LeafIndex& leaves, std::uint64_t key)
    : m_leaves(leaves), m_key(key), m_next_point(leaves.numbers(), 0) {}

void SequenceCursors::advance(std::span<const RayRegion> regions, RayStrata& strata) {
    strata.continue_sequences(m_key);
    for (std::uint32_t l = 0; l < strata.sources(); ++l) {
        const RayRegion& g = regions[l];
        // The domain's centre is inside the leaf whatever the rounding of its boundaries.
        const Vec2 centre =
            Domain{float(g.u0), float(g.v0), float(g.s)}.centre(g.map != RegionMap::triangle);
        const std::size_t leaf = m_leaves.number(g.patch, std::uint8_t(g.side), centre);
        strata.continue_source(l, leaf, m_next_point[leaf]);
        m_next_point[leaf] += strata.first_ray(l + 1) - strata.first_ray(l);
    }
}

}  // namespace hmcr
