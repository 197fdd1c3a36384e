// SPDX-License-Identifier: Apache-2.0
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

// Every pixel's samples of one image as a function of the threshold: what the threshold search
// (trace/trace_image.cpp) probes. PixelRuns runs each pixel on its own; PassRuns
// (trace/pass_runs.h) the image in passes.
class SampleRuns {
public:
    virtual ~SampleRuns() = default;
    // Traces what the image lacks at the threshold (`progress` advanced as it goes); returns the
    // mean samples per pixel at it. A lower threshold only adds samples to a higher one's.
    // Throws Interrupted (common/interrupt.h) after a signal; the runs are then unusable.
    virtual double extend(double threshold, Progress& progress = no_progress()) = 0;

    // After extend(threshold):
    virtual Image image(double threshold) const = 0;
    virtual std::vector<std::uint32_t> samples(double threshold) const = 0;  // per pixel, row-major
    virtual std::uint64_t rays(double threshold) const = 0;
    virtual std::uint64_t rays_traced() const = 0;  // including samples beyond the threshold
    // The criterion's value of each pixel's first samples (after an extend).
    virtual std::vector<double> first_values() const = 0;
};

class PixelRuns final : public SampleRuns {
public:
    PixelRuns(const Criterion& criterion, const RunLimits& limits, const PixelTracer& tracer);
    // Given runs, one per pixel in row-major order.
    PixelRuns(std::vector<std::unique_ptr<PixelRun>> runs, const PixelTracer& tracer)
        : m_tracer(tracer), m_runs(std::move(runs)) {}

    // Traces what every pixel lacks at the threshold (rows in blocks, `progress` advanced
    // between them). Throws Interrupted within a pixel after a signal (PixelRun::extend).
    double extend(double threshold, Progress& progress = no_progress()) override;

    Image image(double threshold) const override;
    std::vector<std::uint32_t> samples(double threshold) const override;
    std::uint64_t rays(double threshold) const override;
    std::uint64_t rays_traced() const override;
    std::vector<double> first_values() const override;

private:
    friend Image fresh_image(const PixelTracer&, const std::vector<std::uint32_t>&, std::uint64_t&,
                             Progress&);
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
