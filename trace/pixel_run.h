// SPDX-License-Identifier: Apache-2.0
// The samples of one pixel as a function of the refinement threshold. A criterion stops
// refining where its value falls to the threshold, so a lower threshold only ever adds samples
// to those a higher one took: a run keeps what it traced, and extend() traces only what a new,
// lower threshold adds. The threshold search (trace/threshold_search.h) probes many thresholds
// for the price of the lowest; the image at the threshold it accepts is assembled from the
// same samples, and equals a fresh render at that threshold bit for bit.
//
// BatchRun (Scheme::uniform and Scheme::batches): batch k holds samples 8k .. 8k + 7, one in
// each of 2 x 4 strata taken in an order drawn for the batch, so that a last, partial batch
// (a target that is not a multiple of 8) takes a uniformly random subset of the strata and the
// pixel's mean stays unbiased. The pixel stops after the first batch whose value is at most the
// threshold, or at max_samples; uniform runs always take max_samples and keep only their sums.
// TreeRun (Scheme::quadtree): the subpixel quadtree of trace/criteria/criterion.h, to
// max_depth (the pixel is depth 0); a node refines when its value exceeds the threshold. The
// pixel's radiance is the mean over its leaves' regions of each leaf's sample mean (Figure 5:
// the colours of the children, each weighed by its area).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "trace/criteria/criterion.h"
#include "trace/pixel_tracer.h"

namespace hmcr {

struct RunLimits {
    std::uint32_t max_samples = 64;  // batches: the most a pixel gets (uniform: exactly this)
    int max_depth = 4;               // quadtree: depth limit (the paper's 4: up to 1,024 samples)
};

inline constexpr std::uint32_t kBatchSize = 8;    // 2 x 4 strata
inline constexpr std::uint32_t kNodeSamples = 4;  // 2 x 2 strata

class PixelRun {
public:
    virtual ~PixelRun() = default;
    // Traces whatever the pixel lacks at this threshold. Throws Interrupted (common/interrupt.h)
    // between its batches or nodes after a signal: one pixel may take up to a million samples.
    virtual void extend(double threshold, const PixelTracer& tracer) = 0;
    // After extend(threshold): the pixel's samples, their mean radiance (box filter) and the
    // rays their paths cast.
    virtual std::uint32_t samples(double threshold) const = 0;
    virtual Rgb radiance(double threshold) const = 0;
    virtual std::uint64_t rays(double threshold) const = 0;
    // Every ray cast so far, also those of samples beyond the current threshold.
    virtual std::uint64_t rays_traced() const = 0;
    // The criterion's value of the first batch or of the pixel's root node (after extend).
    virtual double first_value() const = 0;
};

// The run of pixel (x, y) for the criterion's scheme: make_batch_run (trace/batch_run.cpp) or
// make_tree_run (trace/tree_run.cpp).
std::unique_ptr<PixelRun> make_pixel_run(const Criterion& criterion, const RunLimits& limits, int x,
                                         int y);
std::unique_ptr<PixelRun> make_batch_run(const Criterion& criterion, std::uint32_t max_samples,
                                         int x, int y);
std::unique_ptr<PixelRun> make_tree_run(const Criterion& criterion, int max_depth, int x, int y);
// Samples first .. end - 1 of pixel (x, y), one batch (first a multiple of 8, end - first <= 8),
// in the order of strata drawn for the batch: the batches every batch run takes.
std::vector<TracedSample> trace_pixel_batch(const PixelTracer& tracer, int x, int y,
                                            std::uint32_t first, std::uint32_t end);
// Samples first .. end - 1 of the pixel's uniform batches (first a multiple of 8, at most end):
// the rest of a pixel whose first samples were traced by another run, the same samples a
// uniform run of `end` takes after them. Its radiance is the mean of those samples alone (0 for
// none).
std::unique_ptr<PixelRun> make_uniform_run(std::uint32_t first, std::uint32_t end, int x, int y);

// The most memory one pixel's run holds: every sample it can take kept (a uniform run keeps its
// sums alone), with the spare capacity of growing vectors. An adaptive trace is refused before it
// starts when its pixels would need more than the machine has (trace/trace_image.h).
std::uint64_t pixel_run_bytes(const Criterion& criterion, const RunLimits& limits);
std::uint64_t batch_run_bytes(const Criterion& criterion, std::uint32_t max_samples);
std::uint64_t tree_run_bytes(int max_depth);

}  // namespace hmcr
