// SPDX-License-Identifier: Apache-2.0
// Hypothesis tests for Monte Carlo results. A check fails when the estimate is further from
// the exact value than a few standard errors of the estimator; the standard error comes from
// the estimator's own variance, never from a tuned tolerance.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace hmcr::test {

// z = 4: a correct estimator fails a check about once in 16,000 seeds (two-sided normal).
inline constexpr double kZ = 4.0;

struct Estimate {
    double mean = 0;
    double standard_error = 0;
    std::size_t n = 0;
};

// Sample mean and its standard error (sample standard deviation / sqrt(n)).
Estimate estimate_mean(const std::vector<double>& samples);

// |estimate - expected| <= z * standard_error (+ an exact, stated bias bound, default 0).
testing::AssertionResult within_standard_errors(const std::string& what, double estimate,
                                                double expected, double standard_error,
                                                double bias_bound = 0, double z = kZ);

// One-sample Student t test of the mean of a few independent runs (e.g. one per seed) at
// two-sided level 1e-3 / comparisons: a test that makes `comparisons` of them (one per patch)
// keeps its own false-alarm rate at 1e-3 (Bonferroni). For 2 samples or more.
testing::AssertionResult t_test(const std::string& what, const std::vector<double>& samples,
                                double expected, double bias_bound = 0, int comparisons = 1);

// Pearson's chi-square goodness-of-fit test of observed counts against the expected counts of
// the same cells (the same total), at level 1e-3 / comparisons (Bonferroni): cells expected
// below 5 are pooled into one (Cochran's rule), so that the statistic's chi-square distribution
// holds. The message names the statistic, its degrees of freedom and p-value.
testing::AssertionResult chi_square_test(const std::string& what,
                                         const std::vector<double>& observed,
                                         const std::vector<double>& expected, int comparisons = 1);

// One-sided F test of two independent samples (e.g. one value per seed, two estimators): passes
// when it rejects "var(smaller) >= var(larger)" at level 1e-3. The message names the
// statistic s_larger^2 / s_smaller^2, its degrees of freedom and p-value.
testing::AssertionResult variance_smaller(const std::string& what,
                                          const std::vector<double>& smaller,
                                          const std::vector<double>& larger);

// The upper-tail p-value of a chi-square statistic with `dof` degrees of freedom.
double chi_square_p_value(double statistic, double dof);

// Two-sided p-value of Student's t statistic `t` with `dof` degrees of freedom, and the
// quantile with two-sided level `alpha`.
double student_p_value(double t, double dof);
double student_quantile(double alpha, double dof);

}  // namespace hmcr::test
