// SPDX-License-Identifier: Apache-2.0
// The Sobol sequences a fixed mesh's leaves keep through the iterations of a pass
// (docs/design.md §3.2): a source leaf's rays in an iteration are the points after the ones its
// rays took in the iterations before, so that over the pass each leaf's rays are one scrambled
// low-discrepancy sequence rather than one short sequence an iteration. A leaf is known by its
// number in the pass's leaf index, and its next point follows the strata's dealing alone, which
// every rank and thread count computes alike.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "radiosity/leaf_index.h"
#include "rays/ray_generator.h"
#include "rays/ray_strata.h"

namespace hmcr {

class SequenceCursors {
public:
    // The leaves of `leaves`' mesh, their sequences scrambled by `key`, which no iteration's
    // stream may take; every leaf at its sequence's first point.
    SequenceCursors(const LeafIndex& leaves, std::uint64_t key);

    // Continues `strata`'s sources, the leaves `regions` in order, each on its leaf's sequence
    // (its number) from the point after its last ray so far, and moves each past the rays the
    // strata deal it.
    void advance(std::span<const RayRegion> regions, RayStrata& strata);

private:
    const LeafIndex& m_leaves;
    std::uint64_t m_key;
    std::vector<std::uint64_t> m_next_point;  // a leaf's, by its number
};

}  // namespace hmcr
