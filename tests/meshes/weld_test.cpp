// SPDX-License-Identifier: Apache-2.0
// Welding: exactly equal positions get one id, numbered in order of first appearance, whatever
// the positions' order; -0 and +0 are equal, and nearly equal positions are not.
#include "meshes/weld.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hmcr {
namespace {

using Points = std::vector<Eigen::Vector3d>;

TEST(Weld, EqualPositionsShareTheIdOfTheirFirstAppearance) {
    const Points p{
        {1, 2, 3}, {0, 0, 0}, {1, 2, 3}, {-0.0, 0, -0.0}, {1, 2, std::nextafter(3.0, 4.0)},
        {0, 0, 0}, {1, 2, 3}};
    const Welding w = weld(p);
    EXPECT_EQ(w.id, (std::vector<int>{0, 1, 0, 1, 2, 1, 0}));
    EXPECT_EQ(w.count, 3u);
}

TEST(Weld, AgreesWithAPairwiseComparisonOnManyRepeatedPositions) {
    // 2,000 positions drawn from 300 distinct ones on a coarse grid (many repeats, in no order):
    // the id of each must be the index, among first appearances, of the first equal position.
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(-3, 3);
    Points p;
    for (int k = 0; k < 2000; ++k) p.emplace_back(coord(rng), coord(rng) * 0.5, coord(rng));
    const Welding w = weld(p);
    const std::vector<int>& id = w.id;
    std::vector<std::size_t> firsts;
    for (std::size_t k = 0; k < p.size(); ++k) {
        std::size_t f = 0;
        while (p[f] != p[k]) ++f;
        if (f == k) {
            EXPECT_EQ(id[k], int(firsts.size()));
            firsts.push_back(k);
        } else {
            EXPECT_EQ(id[k], id[f]) << "position " << k;
        }
    }
    EXPECT_EQ(w.count, firsts.size());
}

TEST(Weld, NoPositionsNoIds) {
    const Welding w = weld({});
    EXPECT_TRUE(w.id.empty());
    EXPECT_EQ(w.count, 0u);
}

}  // namespace
}  // namespace hmcr
