// The runs (viz/pixel_run.h) of every pixel of one image: extended together, in parallel, and
// read off at a threshold as the image, its sample counts and its ray count. Each pixel owns
// its samples and streams, so the split into tasks changes nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "common/progress.h"
#include "viz/image.h"
#include "viz/pixel_run.h"

namespace hmcr {

class PixelRuns {
public:
    PixelRuns(const Criterion& criterion, const RunLimits& limits, const PixelTracer& tracer);

    // Traces what every pixel lacks at the threshold (rows in blocks, `progress` advanced
    // between them); returns the mean samples per pixel at it.
    double extend(double threshold, Progress& progress = no_progress());

    // After extend(threshold):
    Image image(double threshold) const;
    std::vector<std::uint32_t> samples(double threshold) const;  // per pixel, row-major
    std::uint64_t rays(double threshold) const;
    std::uint64_t rays_traced() const;  // including samples beyond the threshold
    std::vector<double> first_values() const;

private:
    const PixelTracer& m_tracer;
    std::vector<std::unique_ptr<PixelRun>> m_runs;  // row-major
};

}  // namespace hmcr
