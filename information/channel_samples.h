// SPDX-License-Identifier: Apache-2.0
// Samples of a scene's visibility channel (docs/design.md §7): rays leaving a state (a patch's
// front, or the back of a two-sided one, §7.7) from an area-uniform point in a
// cosine-distributed direction, each with the state it meets first. F_ij is the share of i's
// rays that land on j; misses and hits on the back of a one-sided patch land on no state. Two ways
// to draw them (Sbert, "The use of global random directions to compute radiosity", 1997):
// - local lines: from each patch i, n_i rays with n_i proportional to A_i;
// - global lines: uniformly distributed lines through the scene's bounding sphere. Along a
//   line, every surface hit starts a ray on the patch's front side, ending at the neighbouring
//   hit on that side, so each segment between consecutive hits counts for both end patches.
//   Lines cross a patch in proportion to its area, with cosine-distributed directions on
//   either side: the same distribution as local lines, but with random counts per patch.
// Along every ray that lands on a front face, the continuous kernel log2(A_T F(x, y)) is
// summed for I^c_S.
//
// Line k draws from the keyed stream (seed, key, k) and is traced in fixed blocks, so the
// samples are independent of the thread count. Line k belongs to batch k % batches: every batch
// is an independent replicate, for batch-means standard errors.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "common/progress.h"
#include "rays/embree_scene.h"
#include "rays/patch.h"

namespace hmcr {

enum class LineMethod { local, global };

// "local" or "global"; throws InputError naming the value otherwise.
LineMethod parse_line_method(const std::string& name);
const char* line_method_name(LineMethod method);

struct LineOptions {
    LineMethod method = LineMethod::local;
    // Local: rays in all, shared among patches in proportion to area. Global: lines through
    // the bounding sphere (each gives a sample per surface it crosses).
    std::uint64_t lines = 1'000'000;
    std::uint32_t batches = 16;  // independent batches by line index (batch-means errors)
    std::uint64_t seed = 1;
};

struct ChannelSamples {
    static constexpr std::uint32_t kNoPatch = std::numeric_limits<std::uint32_t>::max();

    std::uint32_t batches = 1;
    std::uint64_t lines = 0;  // lines traced
    // Samples of patch i in batch b: target[first[i * batches + b] .. first[i * batches + b + 1]).
    std::vector<std::uint64_t> first;
    std::vector<std::uint32_t> target;  // front-face hit per sample, or kNoPatch
    // Per batch: sum of log2(A_T F(x, y)) over the rays that land on a front face, and their
    // count (a global segment between two front faces counts once).
    std::vector<double> log_kernel_sum;
    std::vector<std::uint64_t> log_kernel_count;

    std::size_t patches() const { return (first.size() - 1) / batches; }
    std::uint64_t samples() const { return target.size(); }
    std::span<const std::uint32_t> targets(std::size_t patch) const {
        return range(first[patch * batches], first[(patch + 1) * batches]);
    }
    std::span<const std::uint32_t> targets(std::size_t patch, std::uint32_t batch) const {
        const std::size_t k = patch * batches + batch;
        return range(first[k], first[k + 1]);
    }

private:
    std::span<const std::uint32_t> range(std::uint64_t a, std::uint64_t b) const {
        return {target.data() + a, b - a};
    }
};

// Per-batch sums of log2(A_T F) over the rays that land on a front face, and their counts:
// kept per parallel block by the tracers and merged in block order (thread-count independent).
struct KernelTally {
    std::vector<double> sum;
    std::vector<std::uint64_t> count;

    explicit KernelTally(std::uint32_t batches = 0) : sum(batches, 0.0), count(batches, 0) {}
    void add(std::uint32_t batch, double log_kernel) {
        sum[batch] += log_kernel;
        ++count[batch];
    }
    void merge_into(ChannelSamples& out) const;
};

// The batch count of the options (at least 1).
std::uint32_t batch_count(const LineOptions& options);

// Local rays per patch: a multiple of the batch count, at least one per batch, about N a_i.
std::vector<std::uint64_t> local_line_counts(const PatchSet& patches, const LineOptions& options);

class BackSides;

// The tracers report the fraction of lines traced to `progress`. `patches` are the channel's
// states and `scene` holds their fronts; with `backs` (information/back_sides.h) the states
// after the fronts are backs, which rays leave around their own normal and land on when they
// meet a front from behind.
ChannelSamples trace_local_lines(const PatchSet& patches, const EmbreeScene& scene,
                                 const LineOptions& options, Progress& progress = no_progress(),
                                 const BackSides* backs = nullptr);
ChannelSamples trace_global_lines(const PatchSet& patches, const EmbreeScene& scene,
                                  const LineOptions& options, Progress& progress = no_progress(),
                                  const BackSides* backs = nullptr);
// By options.method.
ChannelSamples trace_lines(const PatchSet& patches, const EmbreeScene& scene,
                           const LineOptions& options, Progress& progress = no_progress(),
                           const BackSides* backs = nullptr);

// Runs f(block) for every block in [0, blocks) on all cores, in rounds between which the
// calling thread reports the fraction done.
void parallel_blocks(std::uint64_t blocks, Progress& progress,
                     const std::function<void(std::uint64_t)>& f);

// log2(A_T F(x, y)) between x on p and y on q; NaN when the kernel is 0.
double log_kernel(const Patch& p, const Vec3& x, const Patch& q, const Vec3& y, double total_area);
// The same for the ray from x along the unit direction d that hits q: y is recomputed on q's
// plane in double precision (Embree's distance is a float), which keeps the kernel accurate
// near edges and the estimates scale-equivariant.
double log_kernel_along(const Patch& p, const Vec3& x, const Patch& q, const Vec3& d,
                        double total_area);

}  // namespace hmcr
