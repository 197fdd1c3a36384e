// SPDX-License-Identifier: Apache-2.0
#include "trace/map_allocation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "trace/pixel_runs.h"

namespace hmcr {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The samples each pixel takes beyond the first, as real numbers summing to `extra` in total.
std::vector<double> shares(std::span<const double> values, double extra, double cap) {
    std::vector<double> x(values.size(), 0.0);
    double smallest = kInf;
    std::size_t positive = 0;
    for (double v : values) {
        if (v > 0) {
            smallest = std::min(smallest, v);
            ++positive;
        }
    }
    if (positive == 0) {  // a map of zeros: every pixel the same
        std::fill(x.begin(), x.end(), extra / double(values.size()));
        return x;
    }
    const auto total = [&](double s) {
        double t = 0;
        for (double v : values) t += std::min(cap, s * v);
        return t;
    };
    if (total(cap / smallest) <= extra) {  // every positive pixel at the cap, the rest shared
        const double rest = (extra - cap * double(positive)) / double(values.size() - positive);
        for (std::size_t i = 0; i < values.size(); ++i)
            x[i] = values[i] > 0 ? cap : std::min(cap, rest);
        return x;
    }
    // total(s) grows continuously from 0 to above `extra`: bisection on s.
    double lo = 0, hi = cap / smallest;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (total(mid) < extra ? lo : hi) = mid;
    }
    for (std::size_t i = 0; i < values.size(); ++i) x[i] = std::min(cap, hi * values[i]);
    return x;
}

}  // namespace

std::vector<std::uint32_t> allocate_from_map(std::span<const double> values, double spp,
                                             std::uint32_t first, std::uint32_t most) {
    if (values.empty() || !(spp >= first && spp <= most)) {
        throw std::invalid_argument("allocate_from_map: spp " + std::to_string(spp) + " outside " +
                                    std::to_string(first) + ".." + std::to_string(most));
    }
    for (double v : values) {
        if (!(v >= 0 && std::isfinite(v))) {
            throw std::invalid_argument("allocate_from_map: a value " + std::to_string(v));
        }
    }
    const double extra = (spp - first) * double(values.size());
    const std::vector<double> x = shares(values, extra, double(most - first));
    std::vector<std::uint32_t> counts(values.size());
    double cumulative = 0;
    long long before = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        cumulative += x[i];
        const long long now = std::llround(cumulative);
        const long long a = std::clamp<long long>(now - before, 0, most - first);
        counts[i] = first + std::uint32_t(a);
        before += a;
    }
    return counts;
}

MapTrace trace_from_map(const Criterion& criterion, const PixelTracer& pixels,
                        const PixelTracer* fresh, double spp, std::uint32_t most,
                        Progress& progress) {
    const std::size_t width = std::size_t(pixels.width()), count = width * pixels.height();
    const auto at = [&](std::size_t i) { return std::pair{int(i % width), int(i / width)}; };
    // The first pass: one batch of 8 per pixel and the criterion's value of it.
    std::vector<std::unique_ptr<PixelRun>> runs;
    for (std::size_t i = 0; i < count; ++i) {
        const auto [x, y] = at(i);
        runs.push_back(make_batch_run(criterion, kBatchSize, x, y));
    }
    PixelRuns first(std::move(runs), pixels);
    progress.stage("first pass");
    first.extend(kInf, progress);
    MapTrace out;
    out.values = first.first_values();
    out.samples = allocate_from_map(out.values, spp, kBatchSize, most);
    const std::uint64_t first_rays = first.rays(kInf);
    progress.stage("allocated samples");
    if (fresh) {
        out.image = fresh_image(*fresh, out.samples, out.rays, progress);
        out.rays_traced = first_rays + out.rays;
        return out;
    }
    // The rest of each pixel: samples 8 .. n_i - 1, the same a uniform run of n_i would take.
    std::vector<std::unique_ptr<PixelRun>> rest;
    for (std::size_t i = 0; i < count; ++i) {
        const auto [x, y] = at(i);
        rest.push_back(make_uniform_run(kBatchSize, out.samples[i], x, y));
    }
    PixelRuns second(std::move(rest), pixels);
    second.extend(kInf, progress);
    out.image = first.image(kInf);
    const Image more = second.image(kInf);
    const std::vector<std::uint32_t> n = second.samples(kInf);
    for (std::size_t i = 0; i < count; ++i) {
        if (n[i] == 0) continue;
        out.image.pixels[i] =
            (out.image.pixels[i] * double(kBatchSize) + more.pixels[i] * double(n[i])) /
            double(kBatchSize + n[i]);
    }
    out.rays = first_rays + second.rays(kInf);
    out.rays_traced = out.rays;
    return out;
}

}  // namespace hmcr
