// SPDX-License-Identifier: Apache-2.0
// The papers' protocol of adaptive sampling (`--allocation map`; Rigau, Feixas, Sbert,
// "Refinement criteria based on f-divergences", EGSR 2003, section 5 and Fig. 7, after their
// "New contrast measures for pixel supersampling", CGI 2002): a first uniform pass of 8
// stratified samples per pixel makes a map of the criterion's value of each pixel (the papers'
// "temperature map"), and the rest of the budget is allocated from the map once, in proportion
// to it, every pixel keeping at least its 8. No threshold and no search: the allocation is the
// budget's. The final image reuses the first pass (each pixel the mean of its 8 + a_i samples,
// the papers' way), or with `fresh` is traced again from fresh streams at the same counts
// (Kirk and Arvo's unbiased second pass, at 8 more samples per pixel).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/progress.h"
#include "image/image.h"
#include "trace/pixel_tracer.h"

namespace hmcr {

// Each pixel's count n_i = first + a_i: a_i = min(most - first, s v_i) for the scale s at which
// they sum to (spp - first) x pixels (where the values cannot take it all, the pixels of value 0
// share the rest evenly; all share it evenly when every value is 0), rounded to whole samples
// by cumulative rounding in row-major order, so that the total is kept. Needs
// first <= spp <= most and values finite and not negative; throws std::invalid_argument.
std::vector<std::uint32_t> allocate_from_map(std::span<const double> values, double spp,
                                             std::uint32_t first, std::uint32_t most);

struct MapTrace {
    Image image;                         // linear radiance
    std::vector<std::uint32_t> samples;  // n_i, row-major
    std::vector<double> values;          // the map: each pixel's first-pass value
    std::uint64_t rays = 0;              // cast by the image's samples
    std::uint64_t rays_traced = 0;       // also by the first pass when the image is fresh
};

// The two passes of `criterion` over the image of `pixels`; with `fresh` (a tracer of other
// streams) the final image is traced again from it. Throws Interrupted (common/interrupt.h).
MapTrace trace_from_map(const Criterion& criterion, const PixelTracer& pixels,
                        const PixelTracer* fresh, double spp, std::uint32_t most,
                        Progress& progress = no_progress());

}  // namespace hmcr
