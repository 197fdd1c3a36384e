// SPDX-License-Identifier: Apache-2.0
// half-difference: how far the mean of every second sample is from the mean of all of them.
// Dammertz, Hanika, Keller, Lensch, WSCG 2010, section 2.1: Blender Cycles' noise threshold.
// ("A hierarchical automatic stopping condition for Monte Carlo global illumination".)
//
//   value = sum_c |I_c - A_c| / sqrt(sum_c I_c)
//
// I the mean radiance of the pixel's n samples, A the mean of its samples 1, 3, 5, ... (the
// image of half the samples), per channel c; 0 for a black pixel. The difference of two
// estimates of the same mean measures the noise of I, and dividing by the square root of the
// brightness makes it a relative error, as the eye sees noise (sqrt: the noise of a Poisson-like
// signal grows as its square root). The scheme is Cycles': passes over the image, a batch of 8
// samples each for every pixel still unconverged, where after each pass a pixel is unconverged
// while its value exceeds the threshold or one of its 8 neighbours' does (a dilation by one
// pixel, so that a noisy pixel is not left beside neighbours that stopped by chance). When to
// use it: the baseline of what a renderer user picks today, without the papers' criteria.
#include <cmath>
#include <memory>

#include "trace/criteria/criterion.h"

namespace hmcr {
namespace {

class HalfDifferenceCriterion final : public NamedCriterion {
public:
    HalfDifferenceCriterion()
        : NamedCriterion("half-difference",
                         "|all - half| / sqrt(all) with a dilation, Blender Cycles' noise "
                         "threshold (Dammertz 2010)",
                         Scheme::passes) {}

    double value(std::span<const PixelSample> samples, double) const override {
        Rgb all = Rgb::Zero(), half = Rgb::Zero();
        std::size_t halves = 0;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            all += samples[i].radiance;
            if (i % 2 == 1) {
                half += samples[i].radiance;
                ++halves;
            }
        }
        if (halves == 0) return 0;
        all /= double(samples.size());
        half /= double(halves);
        const double brightness = channel_sum(all);
        if (!(brightness > 0)) return 0;
        return channel_sum((all - half).abs()) / std::sqrt(brightness);
    }
};

}  // namespace

std::unique_ptr<Criterion> make_half_difference_criterion() {
    return std::make_unique<HalfDifferenceCriterion>();
}

}  // namespace hmcr
