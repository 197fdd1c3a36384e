// Form factors between all pairs of patches of a scene, estimated with local lines (SPEC
// section 7): from each patch i, n_i cosine-distributed rays from area-uniform points, with
// n_i proportional to A_i. F_ij is the fraction of i's rays whose first hit is the front face
// of j; misses and back-face hits count for no j (Sbert, "The use of global random directions
// to compute radiosity", 1997, and Feixas et al., "An information theory framework for the
// analysis of scene complexity", Eurographics 1999, for the information measures built on it).
//
// Ray k of patch i draws from the keyed stream (seed, i, k), and the rays are traced in fixed
// blocks, so every result is independent of the thread count. Ray k belongs to batch
// k % batches; n_i is a multiple of the batch count, so every batch is an independent replicate
// with n_i / batches rays from each patch (for batch-means standard errors).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "radiosity/embree_scene.h"
#include "radiosity/patch.h"

namespace hmcr {

struct LocalLineOptions {
    std::uint64_t lines = 1'000'000;  // total N, shared among patches in proportion to area
    std::uint32_t batches = 16;       // independent batches by ray index (batch-means errors)
    std::uint64_t seed = 1;           // keys every ray's stream with (seed, patch, ray)
};

// The first front-face hit of every local line, plus the continuous kernel on its segment.
struct LocalLines {
    static constexpr std::uint32_t kNoPatch = std::numeric_limits<std::uint32_t>::max();

    std::uint32_t batches = 1;
    std::vector<std::uint64_t> first;   // rays of patch i: [first[i], first[i + 1])
    std::vector<std::uint32_t> target;  // front-face hit per ray, or kNoPatch
    // Per batch: sum of log2(A_T F(x_k, y_k)) over the lines with a front hit, and their count.
    std::vector<double> log_kernel_sum;
    std::vector<std::uint64_t> log_kernel_count;

    std::uint64_t lines() const { return target.size(); }
    std::uint64_t rays(std::size_t patch) const { return first[patch + 1] - first[patch]; }
    std::span<const std::uint32_t> targets(std::size_t patch) const {
        return {target.data() + first[patch], rays(patch)};
    }
};

// Rays per patch: a multiple of the batch count, at least one per batch, about N a_i overall.
std::vector<std::uint64_t> local_line_counts(const PatchSet& patches,
                                             const LocalLineOptions& options);

LocalLines trace_local_lines(const PatchSet& patches, const EmbreeScene& scene,
                             const LocalLineOptions& options);

// One row of a sparse form-factor matrix: (j, hits on j), sorted by j; F_ij = count / rays.
struct FormFactorEntry {
    std::uint32_t patch = 0;
    std::uint32_t count = 0;
};

struct SparseFormFactors {
    std::vector<std::vector<FormFactorEntry>> rows;
    std::vector<std::uint64_t> rays;  // n_i: the denominator of row i

    double operator()(std::size_t i, std::size_t j) const;
};

// Row i from the targets of patch i's rays: all of them, or only those of one batch.
std::vector<FormFactorEntry> form_factor_row(std::span<const std::uint32_t> targets,
                                             std::uint32_t batches = 1, std::uint32_t batch = 0);

SparseFormFactors form_factors(const LocalLines& lines);

}  // namespace hmcr
