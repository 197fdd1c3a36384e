// SPDX-License-Identifier: Apache-2.0
// The sequences a fixed mesh's source regions keep through a pass (rays/sequence_cursors.h):
// each region keeps its sequence whatever its place among an iteration's sources, and starts
// each iteration at the point after the rays the strata dealt it before.
#include "rays/sequence_cursors.h"

#include <gtest/gtest.h>

#include <map>
#include <tuple>
#include <vector>

namespace hmcr::test {
namespace {

RayRegion region(std::uint32_t patch, double u0, std::uint16_t side = kFront) {
    return {u0, 0, 0.5, patch, RegionMap::parallelogram, side};
}

TEST(SequenceCursors, ARegionKeepsItsSequenceAndGoesOnFromItsLastPoint) {
    constexpr std::uint64_t kKey = (std::uint64_t(1) << 32) + 5;
    SequenceCursors cursors(kKey);
    // Three iterations over regions that come, go and change places; two differ by side alone.
    const std::vector<std::vector<RayRegion>> iterations{
        {region(0, 0), region(0, 0.5), region(3, 0)},
        {region(3, 0), region(0, 0), region(3, 0, kBack)},
        {region(0, 0.5), region(3, 0, kBack), region(3, 0), region(0, 0)}};
    const std::vector<std::vector<double>> weights{{1, 2, 3}, {4, 1, 1}, {1, 1, 1, 1}};
    std::map<std::tuple<std::uint32_t, double, std::uint16_t>, std::uint64_t> sequence, next;
    std::uint64_t first = 0;
    for (std::size_t t = 0; t < iterations.size(); ++t) {
        RayStrata strata;
        strata.assign(weights[t], 1000 + 37 * t, 0.4, first);
        first += 1000 + 37 * t;
        cursors.advance(iterations[t], strata);
        ASSERT_TRUE(strata.continued());
        EXPECT_EQ(strata.scramble_key(t), kKey);
        for (std::uint32_t l = 0; l < strata.sources(); ++l) {
            const RayRegion& g = iterations[t][l];
            const auto id = std::make_tuple(g.patch, g.u0, g.side);
            sequence.try_emplace(id, sequence.size());  // a new region: the next sequence
            EXPECT_EQ(strata.sequence(l), sequence[id]) << "iteration " << t << ", source " << l;
            EXPECT_EQ(strata.first_point(l), next[id]) << "iteration " << t << ", source " << l;
            next[id] += strata.first_ray(l + 1) - strata.first_ray(l);
        }
    }
    EXPECT_EQ(sequence.size(), 4u);
}

TEST(SequenceCursors, AssignedStrataStartEverySourceAtPointZeroOfItsOwnSequence) {
    RayStrata strata;
    strata.assign(std::vector<double>{1, 1}, 10, 0.5, 40);
    EXPECT_FALSE(strata.continued());
    EXPECT_EQ(strata.sequence(1), 41u);
    EXPECT_EQ(strata.first_point(1), 0u);
    EXPECT_EQ(strata.scramble_key(9), 9u);
    SequenceCursors(7).advance(std::vector<RayRegion>{region(0, 0), region(1, 0)}, strata);
    strata.assign(std::vector<double>{1, 1}, 10, 0.5, 40);  // a new iteration's strata
    EXPECT_FALSE(strata.continued());
}

}  // namespace
}  // namespace hmcr::test
