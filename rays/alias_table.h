// SPDX-License-Identifier: Apache-2.0
// Sampling an index with probability proportional to its weight in O(1): Walker's alias
// method, built with Vose's stable variant ("A linear algorithm for generating random numbers
// with a given distribution", IEEE TSE 1991). Used to pick the source leaf of every ray.
#pragma once

#include <cstdint>
#include <vector>

namespace hmcr {

class AliasTable {
public:
    explicit AliasTable(const std::vector<double>& weights);
    // The table of new weights, in the storage of the old one.
    void assign(const std::vector<double>& weights);

    // Index i with probability weights[i] / (sum of the weights), from one uniform in [0, 1).
    std::size_t sample(double xi) const;

    // Bin floor(xi n) keeps its own index with probability `keep`, else takes `alias`: the
    // layout the vector gathers of rays/ray_generator.cpp read (16 bytes a bin).
    struct Bin {
        double keep;
        std::uint64_t alias;
    };
    const Bin* bins() const { return m_bins.data(); }
    std::size_t size() const { return m_bins.size(); }

private:
    std::vector<Bin> m_bins;
};

}  // namespace hmcr
