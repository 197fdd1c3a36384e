// SPDX-License-Identifier: Apache-2.0
#include "trace/pixel_runs.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

#include "common/interrupt.h"
#include "trace/criteria/registry.h"

namespace hmcr {

std::uint64_t pixel_run_bytes(const Criterion& criterion, const RunLimits& limits) {
    if (criterion.scheme() == Scheme::quadtree) return tree_run_bytes(limits.max_depth);
    return batch_run_bytes(criterion, limits.max_samples);
}

std::unique_ptr<PixelRun> make_pixel_run(const Criterion& criterion, const RunLimits& limits, int x,
                                         int y) {
    if (criterion.scheme() == Scheme::quadtree) {
        return make_tree_run(criterion, limits.max_depth, x, y);
    }
    return make_batch_run(criterion, limits.max_samples, x, y);
}

PixelRuns::PixelRuns(const Criterion& criterion, const RunLimits& limits, const PixelTracer& tracer)
    : m_tracer(tracer) {
    m_runs.reserve(std::size_t(tracer.width()) * std::size_t(tracer.height()));
    for (int y = 0; y < tracer.height(); ++y) {
        for (int x = 0; x < tracer.width(); ++x) {
            m_runs.push_back(make_pixel_run(criterion, limits, x, y));
        }
    }
}

double PixelRuns::extend(double threshold, Progress& progress) {
    const std::size_t width = std::size_t(m_tracer.width()), height = m_runs.size() / width;
    // About 64 blocks: progress for the user, and enough pixels per block to keep every core busy.
    const std::size_t rows = std::max<std::size_t>(1, height / 64);
    for (std::size_t y0 = 0; y0 < height; y0 += rows) {
        const std::size_t end = std::min(height, y0 + rows) * width;
        // Checked per pixel, and within a pixel per batch or node (pixel_run.h), since a block at
        // thousands of samples per pixel takes minutes. An interruption leaves some pixels of the
        // block unextended, but nothing reads the runs after an Interrupted: the run ends.
        tbb::parallel_for(tbb::blocked_range<std::size_t>(y0 * width, end, 16),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              set_tracing_float_mode();
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  throw_if_interrupted();
                                  m_runs[i]->extend(threshold, m_tracer);
                              }
                          });
        progress.advance(double(std::min(height, y0 + rows)) / double(height));
    }
    std::uint64_t total = 0;
    for (std::uint32_t n : samples(threshold)) total += n;
    return double(total) / double(m_runs.size());
}

Image PixelRuns::image(double threshold) const {
    Image image(m_tracer.width(), m_tracer.height());
    for (std::size_t i = 0; i < m_runs.size(); ++i)
        image.pixels[i] = m_runs[i]->radiance(threshold);
    return image;
}

std::vector<std::uint32_t> PixelRuns::samples(double threshold) const {
    std::vector<std::uint32_t> out(m_runs.size());
    for (std::size_t i = 0; i < m_runs.size(); ++i) out[i] = m_runs[i]->samples(threshold);
    return out;
}

std::uint64_t PixelRuns::rays(double threshold) const {
    std::uint64_t total = 0;
    for (const auto& run : m_runs) total += run->rays(threshold);
    return total;
}

std::uint64_t PixelRuns::rays_traced() const {
    std::uint64_t total = 0;
    for (const auto& run : m_runs) total += run->rays_traced();
    return total;
}

std::vector<double> PixelRuns::first_values() const {
    std::vector<double> out;
    out.reserve(m_runs.size());
    for (const auto& run : m_runs) out.push_back(run->first_value());
    return out;
}

Image fresh_image(const PixelTracer& tracer, const std::vector<std::uint32_t>& samples,
                  std::uint64_t& rays, Progress& progress) {
    const Criterion& uniform = uniform_criterion();
    PixelRuns runs(uniform, RunLimits{}, tracer);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const int x = int(i % std::size_t(tracer.width())),
                  y = int(i / std::size_t(tracer.width()));
        runs.m_runs[i] = make_batch_run(uniform, samples[i], x, y);
    }
    const double threshold = std::numeric_limits<double>::infinity();
    runs.extend(threshold, progress);
    rays += runs.rays(threshold);
    return runs.image(threshold);
}

}  // namespace hmcr
