// SPDX-License-Identifier: Apache-2.0
// The Embree floor of a solve: the same number of queries as hmcr made, generated beforehand
// and traced alone, so that the time hmcr spends beyond them is what the benchmark shows.
#pragma once

#include <cstdint>
#include <vector>

#include "radiosity/hierarchy.h"
#include "rays/embree_scene.h"

namespace hmcr::bench {

struct Segment {
    Vec3 from, to;
};

// The median of some timings (the middle one after sorting).
double median(std::vector<double> seconds);

// First-hit rays with area-uniform origins on the patches and cosine directions (`stream` keys
// the random numbers, for chunks), in no order, or `dealt`: one patch's rays together, as the
// Sobol sequence deals a solve's rays to their sources. Only the origins and directions are
// filled.
GeneratedRays first_hit_rays(const PatchSet& set, std::uint64_t n, std::uint64_t stream,
                             bool dealt);
// n_pairs random pairs of `leaves` (of h), `lines` segments between uniform points of each
// pair (consecutive in the result): what a line-based oracle casts.
std::vector<Segment> pair_segments(const Hierarchy& h, const std::vector<const Element*>& leaves,
                                   std::uint64_t n_pairs, int lines, std::uint64_t stream);

// The floor of a whole solve that shot `rays` rays (`dealt` as first_hit_rays()) and cast
// `lines_cast` lines, N_s = lines per pair: those queries, traced as the solve traces them, with
// all the threads the caller's TBB arena allows, in chunks of 2^22 generated between timings (10^8
// rays would not fit in memory at once); a floor of one chunk or less is the median of 3, a longer
// one is timed once (its length steadies it).
double solve_floor_seconds(const EmbreeScene& scene, const Hierarchy& h, std::uint64_t rays,
                           std::uint64_t lines_cast, int lines, bool dealt);

}  // namespace hmcr::bench
