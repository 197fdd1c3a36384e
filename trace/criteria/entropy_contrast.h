// SPDX-License-Identifier: Apache-2.0
// The entropy contrast of a quadtree node's samples, shared by `entropy` and `binary-entropy`.
// Rigau, Feixas, Sbert, "Entropy-based adaptive supersampling", 2003, eqs. 7-11 and 13-19.
//
//   C = delta C^c + (1 - delta) C^g q-bar                                          (eq. 19)
//   C^c = sum_i w_i C_i q_i / sum_i w_i,   q_i = c-bar_i area                       (eqs. 15, 18)
//
// C_i is the contrast of colour channel i's sample values and C^g that of the geometric factors
// cos(theta) / d^2 (eqs. 7, 10): a number in [0, 1], 0 when the values are all equal. The
// importance q_i = c-bar_i / n_r^level of eq. 15 is the channel's mean times the node's share of
// the pixel (area = 4^-level). w = (0.299, 0.587, 0.114) (Rec. 601, the paper's), delta = 0.9
// (its section 4).
//
// hmcr's decision where the paper is silent: the geometric contrast is weighed by the node's
// colour importance q-bar = sum_i w_i q_i / sum_i w_i. The paper's Q_2 (the mean geometric
// factor over n_r^level) is in 1/m^2 while C^c is in radiance, so their sum would depend on the
// units; with q-bar both terms are radiances and delta keeps its meaning, and a dark node's
// edges matter as little as its colour.
#pragma once

#include <span>

#include "trace/criteria/criterion.h"

namespace hmcr {

inline constexpr double kEntropyDelta = 0.9;
inline constexpr double kEntropyWeights[3] = {0.299, 0.587, 0.114};

// A contrast in [0, 1] of non-negative values with a positive sum: 0 when they are all equal.
using ValueContrast = double (*)(std::span<const double> values, double sum);

// C of eq. 19 with `contrast` for every C_i and C^g.
double entropy_contrast(std::span<const PixelSample> samples, double area, ValueContrast contrast);

}  // namespace hmcr
