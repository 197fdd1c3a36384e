// SPDX-License-Identifier: Apache-2.0
#include "trace/criteria/entropy_contrast.h"

#include <vector>

namespace hmcr {
namespace {

// contrast() of the values, 0 when they sum to 0 (a black channel has no contrast to find).
double contrast_of(const std::vector<double>& values, ValueContrast contrast) {
    double sum = 0;
    for (double v : values) sum += v;
    return sum > 0 ? contrast(values, sum) : 0.0;
}

}  // namespace

double entropy_contrast(std::span<const PixelSample> samples, double area, ValueContrast contrast) {
    if (samples.empty()) return 0;
    const double n = double(samples.size());
    std::vector<double> values(samples.size());
    double colour = 0, importance = 0, weights = 0;
    for (int c = 0; c < 3; ++c) {
        double mean = 0;
        for (std::size_t k = 0; k < samples.size(); ++k) {
            values[k] = samples[k].radiance[c];
            mean += values[k] / n;
        }
        const double q = mean * area;  // eq. 15
        colour += kEntropyWeights[c] * contrast_of(values, contrast) * q;
        importance += kEntropyWeights[c] * q;
        weights += kEntropyWeights[c];
    }
    for (std::size_t k = 0; k < samples.size(); ++k) values[k] = samples[k].geometry;
    const double geometric = contrast_of(values, contrast) * importance / weights;
    return kEntropyDelta * colour / weights + (1 - kEntropyDelta) * geometric;
}

}  // namespace hmcr
