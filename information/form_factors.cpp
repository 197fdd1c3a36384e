// SPDX-License-Identifier: Apache-2.0
#include "information/form_factors.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace hmcr {

double SparseFormFactors::operator()(std::size_t i, std::size_t j) const {
    const auto& row = rows[i];
    const auto it =
        std::lower_bound(row.begin(), row.end(), j,
                         [](const FormFactorEntry& e, std::size_t p) { return e.patch < p; });
    if (it == row.end() || it->patch != j) return 0.0;
    return double(it->count) / double(rays[i]);
}

std::vector<FormFactorEntry> form_factor_row(std::span<const std::uint32_t> targets) {
    std::vector<std::uint32_t> hit;
    hit.reserve(targets.size());
    for (std::uint32_t t : targets) {
        if (t != ChannelSamples::kNoPatch) hit.push_back(t);
    }
    std::sort(hit.begin(), hit.end());
    std::vector<FormFactorEntry> row;
    for (std::uint32_t t : hit) {
        if (row.empty() || row.back().patch != t) row.push_back({t, 0});
        ++row.back().count;
    }
    return row;
}

SparseFormFactors form_factors(const ChannelSamples& samples) {
    SparseFormFactors f;
    const std::size_t n = samples.patches();
    f.rows.resize(n);
    f.rays.resize(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        f.rows[i] = form_factor_row(samples.targets(i));
        f.rays[i] = samples.targets(i).size();
    });
    return f;
}

}  // namespace hmcr
