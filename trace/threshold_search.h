// SPDX-License-Identifier: Apache-2.0
// The refinement threshold that gives an adaptive image a target mean number of samples per
// pixel (`hmcr trace --spp N`), found as `--budget` finds epsilon (radiosity/budget_search.h):
// bisection on log threshold, with log-log interpolation inside a bracket.
//
// The mean is a step function of the threshold that falls as the threshold grows. Probes below
// every earlier one trace new samples (trace/pixel_run.h); probes above the lowest cost nothing,
// so outside a bracket the search steps up boldly (a factor 10) and down carefully (a factor
// 1.5, or the secant of the last two probes, at most a factor 4).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/error.h"

namespace hmcr {

struct SppTarget {
    double spp = 0;           // mean samples per pixel
    double tolerance = 0.02;  // accepted relative distance
    int max_probes = 40;
};

struct ThresholdProbe {
    double threshold = 0;
    double spp = 0;
};

// The target cannot be reached: outside what the sampler can give, or a jump of the step
// function across the tolerance.
class SppNotReached : public InputError {
public:
    using InputError::InputError;
};

// spp_at(threshold) is the image's mean at a threshold; start is the first probe (> 0). Returns
// the accepted threshold; every probe is appended to `probes`. Throws SppNotReached.
double search_threshold(const std::function<double(double)>& spp_at, double start,
                        const SppTarget& target, std::vector<ThresholdProbe>& probes);

}  // namespace hmcr
