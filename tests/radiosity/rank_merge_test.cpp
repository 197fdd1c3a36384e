// SPDX-License-Identifier: Apache-2.0
// The pieces of an iteration shared by ranks that need no MPI to test: how rays are sliced, and
// the quanta deposits are counted in (the whole of it, with mpirun, is tests/mpi/).
#include "radiosity/rank_merge.h"

#include <gtest/gtest.h>

#include <limits>

#include "rays/embree_scene.h"

namespace hmcr::test {
namespace {

// Slices of whole packets, so that every rank traces the packets one rank would.
TEST(RankMerge, SlicesCoverTheRaysOnceInOrderInWholePacketsWithinOnePacketOfEachOther) {
    constexpr std::uint64_t packet = EmbreeScene::kPacketRays;
    for (std::uint64_t rays :
         {0ull, 1ull, 2ull, 7ull, 17ull, 33ull, 2'680'000ull, 1'000'000'000'000'007ull}) {
        for (int ranks : {1, 2, 3, 7, 64}) {
            std::uint64_t next = 0, smallest = UINT64_MAX, largest = 0;
            for (int r = 0; r < ranks; ++r) {
                const RaySlice s = slice_of(rays, r, ranks);
                EXPECT_EQ(s.begin, next) << rays << " rays, rank " << r << " of " << ranks;
                EXPECT_TRUE(s.begin % packet == 0 || s.begin == rays) << rays << ", " << r;
                next = s.end;
                smallest = std::min(smallest, s.end - s.begin);
                largest = std::max(largest, s.end - s.begin);
            }
            EXPECT_EQ(next, rays);
            EXPECT_LE(largest - smallest, packet) << rays << " rays, " << ranks << " ranks";
        }
    }
}

// The bound of power_quanta.h: N rays of the largest power, each rounded up, still fit in int64.
TEST(RankMerge, AnIterationOfTheLargestRaysCannotOverflowItsQuanta) {
    const Rgb bound(3.5, 1e-9, 0);
    for (std::uint64_t rays : {1ull, 2'680'000ull, 1'000'000'000'000'000ull}) {
        const PowerQuantum q = PowerQuantum::for_iteration(bound, rays);
        const Quanta one = q.count(bound, 0.999999);
        EXPECT_EQ(one[2], 0);
        for (int c = 0; c < 2; ++c) {
            EXPECT_NEAR(double(one[c]), 0x1p61 / double(rays), 1.0) << c;
            EXPECT_LE(double(one[c]) * double(rays),
                      double(std::numeric_limits<std::int64_t>::max()));
        }
    }
}

// Dithered rounding is unbiased: over evenly spaced dithers the mean count is the power's exact
// multiple of the quantum, even at 10^15 rays, where a ray is only about 2,300 quanta.
TEST(RankMerge, DitheredQuantaAverageToThePowerExactly) {
    const PowerQuantum q = PowerQuantum::for_iteration(Rgb::Constant(1.0), 1'000'000'000'000'000);
    const Rgb power(0.3, 0.7, 1.0 / 3.0);
    constexpr int kDithers = 1 << 12;
    Rgb mean = Rgb::Zero();
    for (int k = 0; k < kDithers; ++k) mean += q.power(q.count(power, (k + 0.5) / kDithers));
    mean /= kDithers;
    // Evenly spaced dithers leave at most 1/kDithers of a quantum.
    EXPECT_TRUE(((mean - power).abs() <= q.watts / kDithers + 1e-15).all())
        << (mean - power).transpose() << " with quantum " << q.watts.transpose();
    const Rgb nearest = q.power(q.count(power, 0.5));
    EXPECT_GT((nearest - power).abs().maxCoeff(), 10 * (mean - power).abs().maxCoeff())
        << "plain rounding was no worse: the test shows nothing";
}

}  // namespace
}  // namespace hmcr::test
