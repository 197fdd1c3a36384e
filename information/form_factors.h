// SPDX-License-Identifier: Apache-2.0
// Sparse form factors between all pairs of a discretisation, from samples of its visibility
// channel (information/channel_samples.h): F_ij is the share of patch i's samples that land on j.
// Rows keep only the patches actually reached, so 100,000 patches fit.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "information/channel_samples.h"

namespace hmcr {

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

// A row from the targets of one patch's samples (misses count in the denominator only).
std::vector<FormFactorEntry> form_factor_row(std::span<const std::uint32_t> targets);

SparseFormFactors form_factors(const ChannelSamples& samples);

}  // namespace hmcr
