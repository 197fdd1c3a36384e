// SPDX-License-Identifier: Apache-2.0
// The spp search on mean-sample functions with known answers: steps of many pixels (as images
// give), a target it cannot reach, and a jump across the tolerance.
#include "trace/threshold_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rays/rng.h"

namespace hmcr::test {
namespace {

// 10,000 pixels, each with a random value v: 8 samples, plus 8 per halving of the threshold
// below v, at most 480; the mean falls as the threshold grows, in steps.
class FakeImage {
public:
    FakeImage() {
        Rng rng(1, 2);
        for (int i = 0; i < 10000; ++i) m_values.push_back(std::exp(8 * rng.uniform() - 8));
    }
    double spp(double threshold) const {
        double total = 0;
        for (double v : m_values) {
            const double halvings = v > threshold ? std::ceil(std::log2(v / threshold)) : 0;
            total += std::min(480.0, 8 + 8 * halvings);
        }
        return total / double(m_values.size());
    }

private:
    std::vector<double> m_values;
};

TEST(ThresholdSearch, ReachesTheTargetWithinTolerance) {
    const FakeImage image;
    for (const double target : {9.0, 24.0, 60.0, 200.0}) {
        for (const double start : {1e-9, 1e-3, 10.0}) {
            std::vector<ThresholdProbe> probes;
            const double t = search_threshold([&](double x) { return image.spp(x); }, start,
                                              {target, 0.02}, probes);
            EXPECT_LE(std::abs(image.spp(t) - target), 0.02 * target) << target << " " << start;
            EXPECT_EQ(probes.back().threshold, t);
            EXPECT_LE(probes.size(), 25u) << target << " " << start;
        }
    }
}

TEST(ThresholdSearch, UnreachableTargetFails) {
    const FakeImage image;
    std::vector<ThresholdProbe> probes;
    EXPECT_THROW(
        search_threshold([&](double x) { return image.spp(x); }, 1e-3, {600, 0.02}, probes),
        SppNotReached);
    EXPECT_EQ(probes.size(), 40u);
}

TEST(ThresholdSearch, JumpAcrossTheToleranceIsReported) {
    std::vector<ThresholdProbe> probes;
    const auto step = [](double x) { return x < 0.5 ? 100.0 : 10.0; };
    try {
        search_threshold(step, 0.01, {50, 0.02}, probes);
        FAIL() << "no error";
    } catch (const SppNotReached& e) {
        EXPECT_NE(std::string(e.what()).find("jumps from 100.00 to 10.00"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace hmcr::test
