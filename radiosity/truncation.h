// SPDX-License-Identifier: Apache-2.0
// What a solve leaves out by stopping: the power still unshot would have been reflected again
// and again. With the reflected fraction r of the last iteration (per channel), the missing
// reflected power is the geometric tail U r / (1 - r) of the unshot power U.
#pragma once

#include "common/types.h"
#include "radiosity/solver.h"

namespace hmcr {

struct TruncationBias {
    Rgb unshot = Rgb::Zero();     // U: power left unshot, W
    Rgb reflected = Rgb::Zero();  // reflected power of the solution, sum A (B - E), W
    Rgb decay = Rgb::Zero();      // r: the last iteration's unshot after / before
    Rgb missing = Rgb::Zero();    // U r / (1 - r): the later bounces' reflected power, W
    Rgb relative = Rgb::Zero();   // missing / reflected: how much too dark the solution is
};

// Of a finished solve (its hierarchy and iteration records).
TruncationBias truncation_bias(const Solution& solution);

// Reflected power sum A (B - E) per channel.
Rgb reflected_power(const Hierarchy& hierarchy);

}  // namespace hmcr
