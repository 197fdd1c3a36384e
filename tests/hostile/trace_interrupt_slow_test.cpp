// SPDX-License-Identifier: Apache-2.0
// SIGTERM ends an adaptive trace within a pixel: one pixel may take up to a million samples
// (minutes), and a cluster's time limit gives seconds. Slow: each case traces for a second first.
#include <signal.h>

#include <chrono>
#include <thread>

#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

class TraceInterrupt : public Hostile, public testing::WithParamInterface<const char*> {};

// A fixed threshold no pixel reaches sends every pixel to its most samples at once: 10^6 for
// kl (batches), 4^11 for entropy at depth 10 (the quadtree). Each took 10 s to minutes after
// the signal.
TEST_P(TraceInterrupt, EndsWithinTwoSecondsOfSigterm) {
    const auto before = snapshot(dir());
    HmcrChild child(
        std::string("trace cube-room -o out/room.png --threshold 1e-30 --progress none ") +
            GetParam(),
        dir(), 120);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    child.signal(SIGTERM);
    const ChildExit e = child.wait();
    EXPECT_EQ(e.code, 128 + SIGTERM) << e.err;
    EXPECT_NE(e.err.find("hmcr: error: interrupted by SIGTERM"), std::string::npos) << e.err;
    EXPECT_LT(e.seconds, 2.0);
    EXPECT_TRUE(snapshot(dir()) == before);
}

INSTANTIATE_TEST_SUITE_P(Samplers, TraceInterrupt,
                         testing::Values("--sampler kl --max-spp 1000000 --width 4",
                                         "--sampler entropy --tree-depth 10 --width 2"),
                         [](const testing::TestParamInfo<const char*>& p) {
                             return std::string(p.index == 0 ? "Batches" : "Quadtree");
                         });

}  // namespace
}  // namespace hmcr::test
