// The runs (trace/pixel_run.h) of every pixel of one image: extended together, in parallel, and
// read off at a threshold as the image, its sample counts and its ray count. Each pixel owns
// its samples and streams, so the split into tasks changes nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "common/progress.h"
#include "image/image.h"
#include "trace/pixel_run.h"

namespace hmcr {

class PixelRuns {
public:
    PixelRuns(const Criterion& criterion, const RunLimits& limits, const PixelTracer& tracer);

    // Traces what every pixel lacks at the threshold (rows in blocks, `progress` advanced
    // between them); returns the mean samples per pixel at it. Throws Interrupted within a
    // pixel after a signal (PixelRun::extend); the runs are then unusable.
    double extend(double threshold, Progress& progress = no_progress());

    // After extend(threshold):
    Image image(double threshold) const;
    std::vector<std::uint32_t> samples(double threshold) const;  // per pixel, row-major
    std::uint64_t rays(double threshold) const;
    std::uint64_t rays_traced() const;  // including samples beyond the threshold
    std::vector<double> first_values() const;

private:
    friend Image fresh_image(const PixelTracer&, const std::vector<std::uint32_t>&,
                             std::uint64_t&, Progress&);
    const PixelTracer& m_tracer;
    std::vector<std::unique_ptr<PixelRun>> m_runs;  // row-major
};

// Kirk and Arvo's second pass ("Unbiased sampling techniques for image synthesis", SIGGRAPH
// 1991): every pixel traced again with fresh samples of `tracer`, as many as `samples` gives it
// (row-major), stratified as uniform runs are. The counts came from other samples, so each
// pixel's mean is unbiased, which the first pass's is not: there a pixel stops on the very
// samples it averages. Adds the rays cast to `rays`.
Image fresh_image(const PixelTracer& tracer, const std::vector<std::uint32_t>& samples,
                  std::uint64_t& rays, Progress& progress = no_progress());

}  // namespace hmcr
