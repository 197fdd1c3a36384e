// SPDX-License-Identifier: Apache-2.0
// The runs of Scheme::passes (trace/criteria/criterion.h), Blender Cycles' adaptive sampling:
// the image in passes rather than each pixel on its own. Pass 0 gives every pixel a batch of 8
// stratified samples (the batches of trace/pixel_run.h, the same samples as any batch run's);
// after pass k, with A_k the pixels that took its batch,
//
//   U_k     = { p in A_k : value of p's samples > threshold, p below its most samples }
//   A_k+1   = { p in A_k : p below its most samples, and p or one of its 8 neighbours in U_k }
//
// (a 3 x 3 dilation of the unconverged pixels, as Cycles' filter passes in x then y give), and
// the image is done when A_k+1 is empty. A pixel that stopped never starts again, so A_k only
// shrinks as the threshold grows: a lower threshold only adds samples to those a higher one
// took, and the threshold search reuses them as it does for the other schemes.
#pragma once

#include <cstdint>
#include <memory>

#include "trace/pixel_runs.h"

namespace hmcr {

// max_samples: the most samples one pixel takes (a multiple of 8 or not: its last batch is then
// partial, as in batch runs).
std::unique_ptr<SampleRuns> make_pass_runs(const Criterion& criterion, std::uint32_t max_samples,
                                           const PixelTracer& tracer);

}  // namespace hmcr
