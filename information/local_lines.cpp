// SPDX-License-Identifier: Apache-2.0
// Local lines: n_i cosine-distributed rays from area-uniform points of each patch i.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/memory.h"
#include "information/back_sides.h"
#include "information/channel_samples.h"
#include "rays/element_sampler.h"
#include "rays/rng.h"
#include "rays/sampling.h"

namespace hmcr {
namespace {

constexpr std::uint64_t kRaysPerTask = 4096;  // rays per parallel task (fixed: results are too)

struct RayOutcome {
    std::uint32_t target = ChannelSamples::kNoPatch;
    double log_kernel = 0;  // log2(A_T F(x, y)), valid when target is a patch
};

// Ray k of state i: an area-uniform origin, a cosine direction, the state it meets first.
RayOutcome trace_ray(const PatchSet& set, const EmbreeScene& scene, const BackSides* backs,
                     std::uint64_t seed, std::uint32_t i, std::uint64_t k) {
    const Patch& p = set.patches[i];
    Rng rng(seed, i, k);
    const double xi1 = rng.uniform(), xi2 = rng.uniform();
    const Vec3 x = p.point(sample_element(p, Domain::root(), xi1, xi2));
    const double xi3 = rng.uniform(), xi4 = rng.uniform();
    const Vec3 d = sample_cosine_hemisphere(p.normal, xi3, xi4);
    const auto hit = scene.first_hit(x, d);
    if (!hit) return {};
    std::uint32_t target = hit->patch;
    if (set.patches[target].normal.dot(d) >= 0) {  // met from behind: a back state, or none
        target = backs ? backs->at(target, x, d, hit->distance) : BackSides::kNoState;
        if (target == BackSides::kNoState) return {};
    }
    const double value = log_kernel_along(p, x, set.patches[target], d, set.total_area);
    if (std::isnan(value)) return {};
    return {target, value};
}

}  // namespace

std::vector<std::uint64_t> local_line_counts(const PatchSet& patches, const LineOptions& options) {
    const std::uint32_t batches = batch_count(options);
    const double per_batch = double(options.lines) / double(batches);
    std::vector<std::uint64_t> n(patches.patches.size());
    for (std::size_t i = 0; i < n.size(); ++i) {
        const double share = per_batch * patches.patches[i].area / patches.total_area;
        n[i] = batches * std::max<std::uint64_t>(1, std::llround(share));
    }
    return n;
}

ChannelSamples trace_local_lines(const PatchSet& patches, const EmbreeScene& scene,
                                 const LineOptions& options, Progress& progress,
                                 const BackSides* backs) {
    ChannelSamples out;
    const std::uint32_t b = out.batches = batch_count(options);
    // One target (4 bytes) per ray, and the slot table: refused before it is allocated.
    require_memory(4.0 * double(options.lines) + 8.0 * double(patches.patches.size()) * b,
                   fmt::format("{} local lines", options.lines));
    const auto counts = local_line_counts(patches, options);
    // Ray k of patch i is number start[i] + k in tracing order; it goes to batch k % b, so every
    // (patch, batch) slot holds counts[i] / b rays.
    std::vector<std::uint64_t> start(counts.size() + 1, 0);
    out.first.assign(counts.size() * b + 1, 0);
    for (std::size_t i = 0; i < counts.size(); ++i) {
        start[i + 1] = start[i] + counts[i];
        for (std::uint32_t s = 0; s < b; ++s) {
            out.first[i * b + s + 1] = start[i] + (s + 1) * (counts[i] / b);
        }
    }
    out.lines = start.back();
    out.target.assign(out.lines, ChannelSamples::kNoPatch);

    const std::uint64_t blocks = (out.lines + kRaysPerTask - 1) / kRaysPerTask;
    std::vector<KernelTally> tallies(blocks, KernelTally(b));
    parallel_blocks(blocks, progress, [&](std::uint64_t block) {
        set_tracing_float_mode();
        const std::uint64_t g0 = block * kRaysPerTask;
        const std::uint64_t g1 = std::min(out.lines, g0 + kRaysPerTask);
        auto i =
            std::uint32_t(std::upper_bound(start.begin(), start.end(), g0) - start.begin() - 1);
        for (std::uint64_t g = g0; g < g1; ++g) {
            while (g >= start[i + 1]) ++i;
            const std::uint64_t k = g - start[i];
            const RayOutcome r = trace_ray(patches, scene, backs, options.seed, i, k);
            out.target[out.first[i * b + k % b] + k / b] = r.target;
            if (r.target != ChannelSamples::kNoPatch) tallies[block].add(k % b, r.log_kernel);
        }
    });
    for (const KernelTally& t : tallies) t.merge_into(out);  // block order: deterministic
    return out;
}

}  // namespace hmcr
