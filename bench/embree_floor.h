// The Embree floor of a solve: the same number of queries as hmcr made, generated beforehand
// and traced alone, so that the time hmcr spends beyond them is what the benchmark shows.
#pragma once

#include <cstdint>
#include <vector>

#include "radiosity/embree_scene.h"
#include "radiosity/hierarchy.h"

namespace hmcr::bench {

struct Ray {
    Vec3 origin, direction;
};
struct Segment {
    Vec3 from, to;
};

// Incoherent first-hit rays: area-uniform origins on the patches, cosine directions.
std::vector<Ray> incoherent_rays(const PatchSet& set, std::uint64_t n);
// n_pairs random pairs of leaves of a solved hierarchy, `lines` segments between uniform
// points of each pair (consecutive in the result): what a line-based oracle casts.
std::vector<Segment> pair_segments(const Hierarchy& h, std::uint64_t n_pairs, int lines);

// Median of 3 timings, with all the threads the caller's TBB arena allows.
double first_hit_seconds(const EmbreeScene& scene, const std::vector<Ray>& rays);
double occlusion_seconds(const EmbreeScene& scene, const std::vector<Segment>& segments, int lines);

}  // namespace hmcr::bench
