// SPDX-License-Identifier: Apache-2.0
#include "meshes/weld.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace hmcr {

// Sorting (position, index) records groups the equal positions; a group's smallest index is its
// first appearance. A sorted array instead of a map: at 10^6 positions the map's node per
// position (an allocation and a tree insert each) was 8% of the load, and more in malloc.
// The key is each coordinate's bits after adding +0, which turns -0 into +0: equal keys are
// equal numbers, and the order is total even for a NaN (std::sort needs one).
Welding weld(const std::vector<Eigen::Vector3d>& positions) {
    if (positions.size() > std::size_t(std::numeric_limits<int>::max())) {
        throw std::length_error("more than 2^31 positions in one mesh");
    }
    struct Record {
        std::array<std::uint64_t, 3> key;
        std::uint32_t index;
    };
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x + 0.0); };
    std::vector<Record> sorted(positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k) {
        const Eigen::Vector3d& p = positions[k];
        sorted[k] = {{bits(p.x()), bits(p.y()), bits(p.z())}, std::uint32_t(k)};
    }
    // Spelled out: std::array's operators call memcmp, which was most of the sort's time.
    const auto same = [](const Record& a, const Record& b) {
        return a.key[0] == b.key[0] && a.key[1] == b.key[1] && a.key[2] == b.key[2];
    };
    std::sort(sorted.begin(), sorted.end(), [](const Record& a, const Record& b) {
        return std::tie(a.key[0], a.key[1], a.key[2], a.index) <
               std::tie(b.key[0], b.key[1], b.key[2], b.index);
    });
    std::vector<int> first(positions.size());  // the first appearance of each one's position
    for (std::size_t s = 0; s < sorted.size(); ++s) {
        const bool starts_group = s == 0 || !same(sorted[s - 1], sorted[s]);
        first[sorted[s].index] = int(starts_group ? sorted[s].index : first[sorted[s - 1].index]);
    }
    Welding w;
    w.id.resize(positions.size());
    int next = 0;
    for (std::size_t k = 0; k < positions.size(); ++k) {
        w.id[k] = first[k] == int(k) ? next++ : w.id[std::size_t(first[k])];
    }
    w.count = std::size_t(next);
    return w;
}

}  // namespace hmcr
