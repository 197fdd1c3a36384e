// SPDX-License-Identifier: Apache-2.0
// The power balance of a solve (docs/design.md §8.4), checked to rounding.
#pragma once

#include "radiosity/solver.h"

namespace hmcr::test {

// Every ray's power is deposited, escapes or hits a back face, and push-pull moves radiosity
// without creating power. Per channel, to rounding:
//   shot = absorbed + reflected (the unshot power of the later iterations) + escaped + back face
// and, summed over channels, where every iteration shoots exactly its unshot channel sum (not so
// with lines used both ways, §3.13, where it holds in expectation; `shoots_its_unshot` false):
//   emitted = absorbed + escaped + back face + unshot remaining.
// For one-sided patches (the absorbed power is read off the patch roots); refined then frozen,
// for the frozen pass, whose values the solution holds.
void expect_energy_balance(const Solution& sol, bool shoots_its_unshot = true);

}  // namespace hmcr::test
