// SPDX-License-Identifier: Apache-2.0
// A criterion that sees display values instead of physical radiance: each sample's radiance
// times an exposure, clamped to [0, 1] per channel, before the wrapped criterion measures it.
//
// The papers' criteria measured RenderPark's colours, whose scale is the display's (the VAR
// tolerance d = 0.025 of Rigau, Feixas, Sbert, EGSR 2003, section 4.2, is a fraction of it).
// hmcr's radiance is physical and unbounded: an emitter's pixels, or a sample that finds the
// light after a bounce, weigh as much as their radiance, although the image shows them as white.
// Clamped at the exposure the image is shown with, a pixel that is saturated on the screen
// looks homogeneous and stops refining.
#pragma once

#include <memory>

#include "trace/criteria/criterion.h"

namespace hmcr {

// `inner` on min(1, exposure x radiance); exposure > 0. `inner` must outlive the result.
std::unique_ptr<Criterion> on_display_values(const Criterion& inner, double exposure);

}  // namespace hmcr
