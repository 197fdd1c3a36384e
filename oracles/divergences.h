// SPDX-License-Identifier: Apache-2.0
// f-divergences of a sampled distribution from the uniform one, shared by the refinement
// oracles (kernel samples of a link) and the pixel sampling criteria (luminances of a pixel's
// samples): one place for D, chi^2 and h^2.
// Rigau, Feixas, Sbert, "Refinement criteria based on f-divergences", EGSR 2003, eqs. 14-16,
// with q_k = 1/n:
//
//   D(p||q)   = sum_k p_k ln(n p_k)                 Kullback-Leibler, in [0, ln n]
//   chi2(p,q) = n sum_k (p_k - 1/n)^2               chi-square, in [0, n - 1]
//   h2(p,q)   = 1/2 sum_k (sqrt(p_k) - sqrt(1/n))^2 squared Hellinger, in [0, 1)
//
// The distribution is given as n non-negative weights and their positive sum, p_k = w_k / sum:
// both callers hold unnormalised values (kernel samples, luminances) and their sum, and
// normalising here spares them a copy. Natural logarithms.
#pragma once

#include <span>

namespace hmcr {

double kl_divergence(std::span<const double> w, double sum);
// sum_k (p_k - 1/n)^2, chi2 without its factor n. The cs oracle multiplies by n after its other
// factors, the order in which it has always computed its value.
double squared_deviation_from_uniform(std::span<const double> w, double sum);
inline double chi_square_divergence(std::span<const double> w, double sum) {
    return double(w.size()) * squared_deviation_from_uniform(w, sum);
}
double hellinger_divergence(std::span<const double> w, double sum);

}  // namespace hmcr
