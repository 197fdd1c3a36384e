// SPDX-License-Identifier: Apache-2.0
// The shared f-divergences (oracles/divergences.h) against values computed by hand, and the
// three oracles that are built on them.
#include "oracles/divergences.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/error.h"
#include "radiosity/oracle_registry.h"

namespace hmcr::test {
namespace {

double sum_of(const std::vector<double>& w) {
    double s = 0;
    for (double x : w) s += x;
    return s;
}

TEST(Divergences, UniformDistributionIsAtZero) {
    const std::vector<double> w = {0.3, 0.3, 0.3, 0.3, 0.3};
    EXPECT_EQ(kl_divergence(w, sum_of(w)), 0);
    EXPECT_NEAR(chi_square_divergence(w, sum_of(w)), 0, 1e-15);
    EXPECT_NEAR(hellinger_divergence(w, sum_of(w)), 0, 1e-15);
}

// p = (0, 0, 0, 1): every divergence at its maximum, D = ln 4, chi2 = n - 1, h2 = 1 - 1/sqrt(n).
TEST(Divergences, PointMassIsAtTheMaximum) {
    const std::vector<double> w = {0, 0, 0, 5};
    EXPECT_NEAR(kl_divergence(w, 5), std::log(4.0), 1e-15);
    EXPECT_NEAR(chi_square_divergence(w, 5), 3, 1e-15);
    EXPECT_NEAR(hellinger_divergence(w, 5), 0.5, 1e-15);
}

// p = (1, 3) / 4 against (1/2, 1/2): D = 1/4 ln(1/2) + 3/4 ln(3/2); chi2 = 2 (1/16 + 1/16);
// h2 = 1/2 ((1/2 - sqrt(1/2))^2 + (sqrt(3)/2 - sqrt(1/2))^2).
TEST(Divergences, TwoPointDistribution) {
    const std::vector<double> w = {1, 3};
    const double r = std::sqrt(0.5);
    EXPECT_NEAR(kl_divergence(w, 4), 0.25 * std::log(0.5) + 0.75 * std::log(1.5), 1e-15);
    EXPECT_NEAR(squared_deviation_from_uniform(w, 4), 0.125, 1e-15);
    EXPECT_NEAR(chi_square_divergence(w, 4), 0.25, 1e-15);
    EXPECT_NEAR(hellinger_divergence(w, 4),
                0.5 * ((0.5 - r) * (0.5 - r) + (std::sqrt(3.0) / 2 - r) * (std::sqrt(3.0) / 2 - r)),
                1e-15);
}

// kl, cs and hl are A_i A_j F^ times these functions, exactly (no second copy of a formula).
TEST(Divergences, OraclesUseThem) {
    const std::vector<double> kernel = {0.1, 2.5, 0, 0.7, 1.3};
    const double f = sum_of(kernel);
    LinkGeometry g;
    g.receiver_area = 2;
    g.source_area = 3;
    g.total_area = 10;
    g.kernel = kernel;
    EXPECT_EQ(find_named(oracle_registry(), "kl").geometric_factor(g),
              2 * 3 * f * kl_divergence(kernel, f));
    EXPECT_EQ(find_named(oracle_registry(), "cs").geometric_factor(g),
              2 * 3 * f * 5.0 * squared_deviation_from_uniform(kernel, f));
    EXPECT_EQ(find_named(oracle_registry(), "hl").geometric_factor(g),
              2 * 3 * f * hellinger_divergence(kernel, f));
}

}  // namespace
}  // namespace hmcr::test
