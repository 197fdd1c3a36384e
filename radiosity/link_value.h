// SPDX-License-Identifier: Apache-2.0
// The oracle's value of a link (docs/design.md §4): the link weight w_ij times the geometric
// factor, from the centre line or from the pair's own N_s lines (through the link cache), for
// the descents of radiosity/refinement.h to compare with the threshold.
#pragma once

#include <cstdint>

#include "radiosity/refinement.h"

namespace hmcr {

// What every link between two patches shares: their normals and the receiver's reflectance
// (or its importance-weighted stand-in), read once for a descent (or a group of them) rather
// than once for each link decided.
struct PatchPair {
    Vec3 receiver_normal, source_normal;
    Rgb reflectance;  // the receiver's
};

PatchPair patch_pair(const RefinementContext& ctx, SideRef receiver, SideRef source);

// The oracle's value of a link: w_ij times its geometric factor, to be compared with
// epsilon * Phi_max. Counted as `rays` decisions (oracle_calls) when the link carries anything.
double link_value(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                  const Element& source, RefinementCounters& counters, std::uint64_t rays);

}  // namespace hmcr
