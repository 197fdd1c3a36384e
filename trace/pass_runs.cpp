// SPDX-License-Identifier: Apache-2.0
#include "trace/pass_runs.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "common/interrupt.h"
#include "rays/embree_scene.h"

namespace hmcr {
namespace {

// One pixel's batches so far and, after each, the criterion's value and the running sums.
struct PassPixel {
    std::vector<StoredSample> samples;
    std::vector<double> value;
    std::vector<Rgb> sum;
    std::vector<std::uint64_t> rays;
};

class PassRuns final : public SampleRuns {
public:
    PassRuns(const Criterion& criterion, std::uint32_t max_samples, const PixelTracer& tracer)
        : m_criterion(criterion),
          m_max(max_samples),
          m_tracer(tracer),
          m_width(std::size_t(tracer.width())),
          m_height(std::size_t(tracer.height())),
          m_pixels(m_width * m_height),
          m_stop(m_pixels.size(), 0) {}

    double extend(double threshold, Progress& progress) override;

    Image image(double) const override {
        Image image{int(m_width), int(m_height)};
        for (std::size_t i = 0; i < m_pixels.size(); ++i)
            image.pixels[i] = m_pixels[i].sum[m_stop[i]] / double(count(m_stop[i]));
        return image;
    }
    std::vector<std::uint32_t> samples(double) const override {
        std::vector<std::uint32_t> out(m_pixels.size());
        for (std::size_t i = 0; i < m_pixels.size(); ++i) out[i] = count(m_stop[i]);
        return out;
    }
    std::uint64_t rays(double) const override {
        std::uint64_t total = 0;
        for (std::size_t i = 0; i < m_pixels.size(); ++i) total += m_pixels[i].rays[m_stop[i]];
        return total;
    }
    std::uint64_t rays_traced() const override {
        std::uint64_t total = 0;
        for (const PassPixel& p : m_pixels) total += p.rays.empty() ? 0 : p.rays.back();
        return total;
    }
    std::vector<double> first_values() const override {
        std::vector<double> out;
        out.reserve(m_pixels.size());
        for (const PassPixel& p : m_pixels) out.push_back(p.value.front());
        return out;
    }

private:
    // Samples after batch k.
    std::uint32_t count(std::size_t k) const {
        return std::min(kBatchSize * std::uint32_t(k + 1), m_max);
    }
    void add_batch(std::size_t i);
    // Gives batch `k` to every pixel of `active` that lacks it, in parallel.
    void trace_pass(const std::vector<std::uint32_t>& active, std::size_t k);
    // Whether pixel i or one of its 8 neighbours is flagged.
    bool near(const std::vector<char>& flagged, std::size_t i) const;

    const Criterion& m_criterion;
    std::uint32_t m_max;
    const PixelTracer& m_tracer;
    std::size_t m_width, m_height;
    std::vector<PassPixel> m_pixels;  // row-major
    std::vector<std::size_t> m_stop;  // the batch after which each pixel stops, at the last extend
};

void PassRuns::add_batch(std::size_t i) {
    PassPixel& p = m_pixels[i];
    const std::size_t b = p.value.size();
    Rgb sum = b ? p.sum.back() : Rgb::Zero();
    std::uint64_t rays = b ? p.rays.back() : 0;
    const int x = int(i % m_width), y = int(i / m_width);
    for (const TracedSample& t :
         trace_pixel_batch(m_tracer, x, y, kBatchSize * std::uint32_t(b), count(b))) {
        p.samples.push_back(store(t.sample));
        sum += t.sample.radiance;
        rays += t.rays;
    }
    p.sum.push_back(sum);
    p.rays.push_back(rays);
    std::vector<PixelSample> all;
    all.reserve(p.samples.size());
    for (const StoredSample& s : p.samples) all.push_back(s.expand());
    p.value.push_back(m_criterion.value(all, 1.0));
}

void PassRuns::trace_pass(const std::vector<std::uint32_t>& active, std::size_t k) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, active.size(), 16),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          set_tracing_float_mode();
                          for (std::size_t j = r.begin(); j < r.end(); ++j) {
                              throw_if_interrupted();
                              if (m_pixels[active[j]].value.size() == k) add_batch(active[j]);
                          }
                      });
}

bool PassRuns::near(const std::vector<char>& flagged, std::size_t i) const {
    const std::size_t x = i % m_width, y = i / m_width;
    for (std::size_t v = y ? y - 1 : 0; v <= std::min(y + 1, m_height - 1); ++v)
        for (std::size_t u = x ? x - 1 : 0; u <= std::min(x + 1, m_width - 1); ++u)
            if (flagged[v * m_width + u]) return true;
    return false;
}

double PassRuns::extend(double threshold, Progress& progress) {
    std::vector<std::uint32_t> active(m_pixels.size());
    for (std::size_t i = 0; i < active.size(); ++i) active[i] = std::uint32_t(i);
    const std::size_t batches = (m_max + kBatchSize - 1) / kBatchSize;
    std::vector<char> unconverged(m_pixels.size(), 0);
    for (std::size_t k = 0; !active.empty(); ++k) {
        trace_pass(active, k);
        progress.advance(double(k + 1) / double(batches));
        for (std::uint32_t i : active)
            unconverged[i] = m_pixels[i].value[k] > threshold && count(k) < m_max;
        std::vector<std::uint32_t> next;
        for (std::uint32_t i : active) {
            if (count(k) < m_max && near(unconverged, i)) {
                next.push_back(i);
            } else {
                m_stop[i] = k;
            }
        }
        for (std::uint32_t i : active) unconverged[i] = 0;
        active = std::move(next);
    }
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < m_pixels.size(); ++i) total += count(m_stop[i]);
    return double(total) / double(m_pixels.size());
}

}  // namespace

std::unique_ptr<SampleRuns> make_pass_runs(const Criterion& criterion, std::uint32_t max_samples,
                                           const PixelTracer& tracer) {
    return std::make_unique<PassRuns>(criterion, max_samples, tracer);
}

}  // namespace hmcr
