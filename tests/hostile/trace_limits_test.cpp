// SPDX-License-Identifier: Apache-2.0
// Hostile trace options: values the messages exclude but that were once accepted (an empty view
// name, a width or max-spp of 0), and an adaptive trace whose kept samples cannot fit in memory,
// refused before it traces (docs/usage.md#bad-input).
#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

TEST_F(Hostile, EmptyAndZeroTraceOptionsAreRefused) {
    plates();
    refused("trace plates.json -o x.png --width 0", "width must be in 1..16384, got 0");
    refused("trace-reference plates.json --width 0 -o ref", "width must be in 1..16384, got 0");
    refused("trace plates.json -o x.png --sampler kl --max-spp 0",
            "max-spp must be in 8..1000000, got 0");
    refused("trace plates.json -o x.png --sampler kl --max-spp 1000001",
            "max-spp must be in 8..1000000, got 1000001");
    refused("trace plates.json -o x.png --view ''", "view: the name is empty");
    refused("render none.vtp --scene plates.json -o x.png --view ''", "view: the name is empty");
}

// Every sample of every pixel is kept: 1024 x 1024 pixels at up to 10^6 samples each is tens of
// terabytes. Refused at once, naming what to lower.
TEST_F(Hostile, AnAdaptiveTraceThatCannotFitInMemoryIsRefusedBeforeTracing) {
    plates();
    const auto before = snapshot(dir());
    HmcrChild child(
        "trace plates.json -o x.png --sampler kl --spp 16 --max-spp 1000000 "
        "--width 1024",
        dir(), 20);
    const ChildExit e = child.wait();
    EXPECT_EQ(e.code, 2) << e.err;
    EXPECT_NE(e.err.find("tracing 1024 x 1024 pixels at up to 1000000 samples each, every sample "
                         "kept, would need about"),
              std::string::npos)
        << e.err;
    EXPECT_NE(e.err.find(": lower --max-spp (default 8 x --spp) or --width\n"), std::string::npos)
        << e.err;
    EXPECT_LT(e.seconds, 2.0);
    EXPECT_TRUE(snapshot(dir()) == before);
    refused("trace plates.json -o x.png --sampler entropy --spp 16 --tree-depth 12 --width 1024",
            "lower --tree-depth or --width");
}

}  // namespace
}  // namespace hmcr::test
