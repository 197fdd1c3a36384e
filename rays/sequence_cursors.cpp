// SPDX-License-Identifier: Apache-2.0
#include "rays/sequence_cursors.h"

#include <bit>
#include <boost/container_hash/hash.hpp>

namespace hmcr {

std::size_t SequenceCursors::RegionHash::operator()(const Region& r) const {
    std::size_t h = 0;
    boost::hash_combine(h, r.u0);
    boost::hash_combine(h, r.v0);
    boost::hash_combine(h, r.s);
    boost::hash_combine(h, r.patch);
    boost::hash_combine(h, r.side);
    return h;
}

void SequenceCursors::advance(std::span<const RayRegion> regions, RayStrata& strata) {
    strata.continue_sequences(m_key);
    for (std::uint32_t l = 0; l < strata.sources(); ++l) {
        const RayRegion& g = regions[l];
        const Region key{std::bit_cast<std::uint64_t>(g.u0), std::bit_cast<std::uint64_t>(g.v0),
                         std::bit_cast<std::uint64_t>(g.s), g.patch, g.side};
        Cursor& c = m_cursors.try_emplace(key, Cursor{m_cursors.size(), 0}).first->second;
        strata.continue_source(l, c.sequence, c.next_point);
        c.next_point += strata.first_ray(l + 1) - strata.first_ray(l);
    }
}

}  // namespace hmcr
