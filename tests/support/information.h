// SPDX-License-Identifier: Apache-2.0
// Helpers for the scene-information tests: measures with their plug-in bias bound, and the
// scenes with exact channels.
//
// Paninski's bound (Neural Computation 2003): a row of K reachable patches estimated from n
// rays has 0 <= H - E[H_hat] <= log2(1 + (K - 1) / n). H_S is an a-weighted mean of row
// entropies and the rest of I_S is linear in F, so H_S is biased down and I_S up by at most
// sum_i a_i log2(1 + (K - 1) / n_i). With global lines n_i is random, but given n_i the rays of
// patch i are independent (a line crosses a flat patch at most once), so the bound holds for
// the realised counts.
#pragma once

#include "information/channel_samples.h"
#include "information/scene_information.h"
#include "rays/patch.h"
#include "tests/support/statistics.h"

namespace hmcr::test {

struct MeasuredChannel {
    InformationMeasures measures;
    double bias_bound = 0;  // on H_S (downward), I_S and H_J (upward), in bits
    Estimate open_share;    // of the rays with no front-face hit, with its batch-means error
};

double plug_in_bias_bound(const PatchSet& set, const ChannelSamples& samples);

MeasuredChannel measure_channel(const PatchSet& set, const LineOptions& options);

// The empty cube's channel, exactly: every face sees the opposite one with F = 0.19982 and
// each of the four adjacent ones with F = 0.20004 (docs/design.md §8), and a_i = 1/6.
struct EmptyCube {
    double opposite, adjacent;  // the two form factors
    double h_p, h_s, i_s;       // bits
};
EmptyCube empty_cube();

// The inward box [0, size]^3, each face split into n x n quads.
PatchSet cube_patches(double size, int n);

// The bundled Cornell box's patches.
PatchSet cornell_patches();

}  // namespace hmcr::test
