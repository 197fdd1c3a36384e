// SPDX-License-Identifier: Apache-2.0
// BatchRun of trace/pixel_run.h: stratified batches of 8 samples until the criterion holds.
#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/interrupt.h"
#include "trace/pixel_run.h"

namespace hmcr {
namespace {

// Keys of the streams that order each batch's strata, apart from the samples' keys (0, 1, ...).
constexpr std::uint64_t kOrderKey = std::uint64_t(1) << 63;

// Stratum s of a batch: column s % 2 of 2, row s / 2 of 4.
Stratum batch_stratum(int s) {
    const int column = s % 2, row = s / 2;
    return {0.5 * column, 0.25 * row, 0.5, 0.25};
}

// A uniformly random order of the 8 strata (Fisher-Yates).
std::array<int, kBatchSize> stratum_order(Rng rng) {
    std::array<int, kBatchSize> order;
    for (int i = 0; i < int(kBatchSize); ++i) order[i] = i;
    for (int i = int(kBatchSize) - 1; i > 0; --i) {
        const int j = std::min(i, int(rng.uniform() * (i + 1)));
        std::swap(order[i], order[j]);
    }
    return order;
}

// Traces samples first .. end - 1 (one batch: first a multiple of 8, end - first <= 8) in the
// order of strata drawn for the batch, handing each to `take`.
template <class Take>
void trace_batch(const PixelTracer& tracer, int x, int y, std::uint32_t first, std::uint32_t end,
                 Take&& take) {
    const auto order = stratum_order(tracer.stream(x, y, kOrderKey | (first / kBatchSize)));
    for (std::uint32_t s = first; s < end; ++s)
        take(tracer.sample(x, y, s, batch_stratum(order[s - first])));
}

class BatchRun final : public PixelRun {
public:
    BatchRun(const Criterion& criterion, std::uint32_t max_samples, int x, int y)
        : m_criterion(criterion), m_max(max_samples), m_x(x), m_y(y) {}

    void extend(double threshold, const PixelTracer& tracer) override {
        while (stop_batch(threshold) == m_value.size()) {
            throw_if_interrupted();
            add_batch(tracer);
        }
    }
    std::uint32_t samples(double threshold) const override { return count(stop_batch(threshold)); }
    Rgb radiance(double threshold) const override {
        const std::size_t k = stop_batch(threshold);
        return m_sum[k] / double(count(k));
    }
    std::uint64_t rays(double threshold) const override { return m_rays[stop_batch(threshold)]; }
    std::uint64_t rays_traced() const override { return m_rays.empty() ? 0 : m_rays.back(); }
    double first_value() const override { return m_value.front(); }

private:
    // Samples after batch k.
    std::uint32_t count(std::size_t k) const {
        return std::min(kBatchSize * std::uint32_t(k + 1), m_max);
    }
    // The batch after which the pixel stops at this threshold; m_value.size() if it needs more.
    std::size_t stop_batch(double threshold) const {
        for (std::size_t k = 0; k < m_value.size(); ++k) {
            if (m_value[k] <= threshold || count(k) >= m_max) return k;
        }
        return m_value.size();
    }
    void add_batch(const PixelTracer& tracer);

    const Criterion& m_criterion;
    std::uint32_t m_max;
    int m_x, m_y;
    std::vector<StoredSample> m_samples;
    std::vector<double> m_value;        // the criterion after batch k
    std::vector<Rgb> m_sum;             // radiance summed over batches 0..k
    std::vector<std::uint64_t> m_rays;  // rays of batches 0..k
};

void BatchRun::add_batch(const PixelTracer& tracer) {
    const std::size_t b = m_value.size();
    Rgb sum = b ? m_sum.back() : Rgb::Zero();
    std::uint64_t rays = b ? m_rays.back() : 0;
    trace_batch(tracer, m_x, m_y, kBatchSize * std::uint32_t(b), count(b),
                [&](const TracedSample& t) {
                    m_samples.push_back(store(t.sample));
                    sum += t.sample.radiance;
                    rays += t.rays;
                });
    m_sum.push_back(sum);
    m_rays.push_back(rays);
    std::vector<PixelSample> all;
    all.reserve(m_samples.size());
    for (const StoredSample& s : m_samples) all.push_back(s.expand());
    m_value.push_back(m_criterion.value(all, 1.0));
}

// A uniform pixel takes the same batches in the same order as a BatchRun but never stops
// early, so it keeps only the running sums: a 4,096-spp reference would otherwise hold every
// sample of every pixel (tens of GB at 256 x 256).
class UniformRun final : public PixelRun {
public:
    // Samples first .. end - 1 (first a multiple of 8).
    UniformRun(std::uint32_t first, std::uint32_t end, int x, int y)
        : m_first(first), m_max(end), m_done(first), m_x(x), m_y(y) {}

    void extend(double, const PixelTracer& tracer) override {
        for (; m_done < m_max; m_done = std::min(m_done + kBatchSize, m_max)) {
            throw_if_interrupted();
            trace_batch(tracer, m_x, m_y, m_done, std::min(m_done + kBatchSize, m_max),
                        [&](const TracedSample& t) {
                            m_sum += t.sample.radiance;
                            m_rays += t.rays;
                        });
        }
    }
    std::uint32_t samples(double) const override { return m_done - m_first; }
    Rgb radiance(double) const override {
        return m_done > m_first ? Rgb(m_sum / double(m_done - m_first)) : Rgb::Zero();
    }
    std::uint64_t rays(double) const override { return m_rays; }
    std::uint64_t rays_traced() const override { return m_rays; }
    double first_value() const override { return std::numeric_limits<double>::quiet_NaN(); }

private:
    std::uint32_t m_first, m_max, m_done;
    int m_x, m_y;
    Rgb m_sum = Rgb::Zero();
    std::uint64_t m_rays = 0;
};

}  // namespace

std::uint64_t batch_run_bytes(const Criterion& criterion, std::uint32_t max_samples) {
    if (criterion.scheme() == Scheme::uniform) return sizeof(UniformRun);
    const std::uint64_t batches = (std::uint64_t(max_samples) + kBatchSize - 1) / kBatchSize;
    const std::uint64_t kept = std::uint64_t(max_samples) * sizeof(StoredSample) +
                               batches * (sizeof(double) + sizeof(Rgb) + sizeof(std::uint64_t));
    return sizeof(BatchRun) + 2 * kept;  // a vector's capacity grows to up to twice its size
}

std::unique_ptr<PixelRun> make_batch_run(const Criterion& criterion, std::uint32_t max_samples,
                                         int x, int y) {
    if (criterion.scheme() == Scheme::uniform) {
        return std::make_unique<UniformRun>(0, max_samples, x, y);
    }
    return std::make_unique<BatchRun>(criterion, max_samples, x, y);
}

std::vector<TracedSample> trace_pixel_batch(const PixelTracer& tracer, int x, int y,
                                            std::uint32_t first, std::uint32_t end) {
    std::vector<TracedSample> out;
    out.reserve(end - first);
    trace_batch(tracer, x, y, first, end, [&](const TracedSample& t) { out.push_back(t); });
    return out;
}

std::unique_ptr<PixelRun> make_uniform_run(std::uint32_t first, std::uint32_t end, int x, int y) {
    if (first % kBatchSize != 0 || first > end) {
        throw std::invalid_argument("make_uniform_run: samples " + std::to_string(first) + ".." +
                                    std::to_string(end));
    }
    return std::make_unique<UniformRun>(first, end, x, y);
}

}  // namespace hmcr
