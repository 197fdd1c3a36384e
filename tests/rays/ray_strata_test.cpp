// SPDX-License-Identifier: Apache-2.0
// The strata that deal an iteration's rays to its sources (rays/ray_strata.h): every ray has one
// source, each source's count is within one of its share, over the offset the count's mean is
// the share exactly, and each source's rays are the points of the sequence the strata name.
#include "rays/ray_strata.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

namespace hmcr::test {
namespace {

const std::vector<double> kWeights{0.5, 0, 3.25, 1e-9, 7, 0, 0.125, 2};

TEST(RayStrata, EverySourceGetsItsShareWithinOneRay) {
    const double total = std::accumulate(kWeights.begin(), kWeights.end(), 0.0);
    for (const std::uint64_t rays : {1u, 7u, 1000u, 123457u}) {
        for (const double offset : {0.0, 0.3, 0.999999}) {
            RayStrata s;
            s.assign(kWeights, rays, offset, 50);
            ASSERT_EQ(s.sources(), kWeights.size());
            EXPECT_EQ(s.first_ray(0), 50u);
            EXPECT_EQ(s.first_ray(std::uint32_t(kWeights.size())), 50 + rays);
            for (std::uint32_t l = 0; l < kWeights.size(); ++l) {
                const double count = double(s.first_ray(l + 1) - s.first_ray(l));
                const double share = double(rays) * kWeights[l] / total;
                EXPECT_LT(std::abs(count - share), 1.0) << rays << " rays, source " << l;
                if (kWeights[l] == 0) {
                    EXPECT_EQ(count, 0) << rays << " rays, source " << l;
                }
            }
            for (std::uint64_t r = 50; r < 50 + rays; r += 1 + rays / 97) {
                const std::uint32_t l = s.source_of(r);
                EXPECT_LE(s.first_ray(l), r);
                EXPECT_LT(r, s.first_ray(l + 1));
            }
        }
    }
}

// Systematic sampling is unbiased: a source's count, averaged over offsets spread evenly over
// [0, 1), is its share up to the midpoint rule's error (the count is a step function of the
// offset with a single step, so 2^20 offsets give it to 2^-20 of a ray).
TEST(RayStrata, TheMeanCountOverTheOffsetIsTheShare) {
    const double total = std::accumulate(kWeights.begin(), kWeights.end(), 0.0);
    const std::uint64_t rays = 1001;
    const int offsets = 1 << 20;
    std::vector<double> sum(kWeights.size());
    RayStrata s;
    for (int k = 0; k < offsets; ++k) {
        s.assign(kWeights, rays, (k + 0.5) / offsets);
        for (std::uint32_t l = 0; l < kWeights.size(); ++l) {
            sum[l] += double(s.first_ray(l + 1) - s.first_ray(l));
        }
    }
    for (std::uint32_t l = 0; l < kWeights.size(); ++l) {
        EXPECT_NEAR(sum[l] / offsets, double(rays) * kWeights[l] / total, 2.0 / offsets)
            << "source " << l;
    }
}

// Assigned strata start every source at point 0 of its own sequence (l + first()), scrambled by
// the iteration's key; continued ones take the sources' own, until the next assign.
TEST(RayStrata, AssignedStrataStartEverySourceAtPointZeroOfItsOwnSequence) {
    RayStrata strata;
    strata.assign(std::vector<double>{1, 1}, 10, 0.5, 40);
    EXPECT_FALSE(strata.continued());
    EXPECT_EQ(strata.sequence(1), 41u);
    EXPECT_EQ(strata.first_point(1), 0u);
    EXPECT_EQ(strata.scramble_key(9), 9u);
    strata.continue_sequences(7);
    strata.continue_source(0, 12, 0);
    strata.continue_source(1, 3, 500);
    EXPECT_TRUE(strata.continued());
    EXPECT_EQ(strata.sequence(1), 3u);
    EXPECT_EQ(strata.first_point(1), 500u);
    EXPECT_EQ(strata.scramble_key(9), 7u);
    strata.assign(std::vector<double>{1, 1}, 10, 0.5, 40);  // a new iteration's strata
    EXPECT_FALSE(strata.continued());
    EXPECT_EQ(strata.sequence(1), 41u);
}

}  // namespace
}  // namespace hmcr::test
