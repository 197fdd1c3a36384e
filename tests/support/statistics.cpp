// SPDX-License-Identifier: Apache-2.0
#include "tests/support/statistics.h"

#include <array>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <sstream>

namespace hmcr::test {

Estimate estimate_mean(const std::vector<double>& samples) {
    Estimate e;
    e.n = samples.size();
    double sum = 0, sum2 = 0;
    for (double x : samples) sum += x;
    e.mean = sum / double(e.n);
    for (double x : samples) sum2 += (x - e.mean) * (x - e.mean);
    e.standard_error = e.n > 1 ? std::sqrt(sum2 / double(e.n - 1) / double(e.n)) : 0;
    return e;
}

testing::AssertionResult within_standard_errors(const std::string& what, double estimate,
                                                double expected, double standard_error,
                                                double bias_bound, double z) {
    const double dev = std::abs(estimate - expected);
    const double limit = z * standard_error + bias_bound;
    std::ostringstream msg;
    msg << what << ": estimate " << estimate << ", expected " << expected << ", |difference| "
        << dev << (dev <= limit ? " <= " : " > ") << z << " standard errors (" << standard_error
        << ")" << (bias_bound > 0 ? " + bias bound " + std::to_string(bias_bound) : "");
    return dev <= limit ? testing::AssertionSuccess() << msg.str()
                        : testing::AssertionFailure() << msg.str();
}

namespace {

// The regularized incomplete beta function I_x(a, b), from its continued fraction evaluated by
// the modified Lentz method (the standard expansion, converging for x < (a + 1) / (a + b + 2)).
double beta_fraction(double a, double b, double x) {
    constexpr double kTiny = 1e-300;
    const auto guard = [](double v) { return std::abs(v) < kTiny ? kTiny : v; };
    double c = 1, d = 1 / guard(1 - (a + b) * x / (a + 1)), h = d;
    for (int m = 1; m <= 500; ++m) {
        const double m2 = 2.0 * m;
        double aa = m * (b - m) * x / ((a - 1 + m2) * (a + m2));
        d = 1 / guard(1 + aa * d);
        c = guard(1 + aa / c);
        h *= d * c;
        aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + 1 + m2));
        d = 1 / guard(1 + aa * d);
        c = guard(1 + aa / c);
        h *= d * c;
        if (std::abs(d * c - 1) < 1e-15) break;
    }
    return h;
}

double incomplete_beta(double a, double b, double x) {
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                  a * std::log(x) + b * std::log1p(-x));
    if (x < (a + 1) / (a + b + 2)) return front * beta_fraction(a, b, x) / a;
    return 1 - front * beta_fraction(b, a, 1 - x) / b;
}

}  // namespace

double student_p_value(double t, double dof) {
    return incomplete_beta(dof / 2, 0.5, dof / (dof + t * t));
}

double student_quantile(double alpha, double dof) {
    double lo = 0, hi = 1e7;  // p falls from 1 to below any alpha used here
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (student_p_value(mid, dof) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

testing::AssertionResult t_test(const std::string& what, const std::vector<double>& samples,
                                double expected, double bias_bound, int comparisons) {
    const Estimate e = estimate_mean(samples);
    if (e.n < 2) return testing::AssertionFailure() << "t_test needs 2 samples or more";
    const double t = student_quantile(1e-3 / comparisons, double(e.n - 1));
    return within_standard_errors(what + " (t test, " + std::to_string(e.n) + " runs)", e.mean,
                                  expected, e.standard_error, bias_bound, t);
}

testing::AssertionResult variance_smaller(const std::string& what,
                                          const std::vector<double>& smaller,
                                          const std::vector<double>& larger) {
    const Estimate s = estimate_mean(smaller), l = estimate_mean(larger);
    if (s.n < 2 || l.n < 2) return testing::AssertionFailure() << what << ": 2 samples or more";
    const double var_s = s.standard_error * s.standard_error * double(s.n);
    const double var_l = l.standard_error * l.standard_error * double(l.n);
    const double d_l = double(l.n - 1), d_s = double(s.n - 1);
    const double p = var_s > 0 ? boost::math::cdf(boost::math::complement(
                                     boost::math::fisher_f(d_l, d_s), var_l / var_s))
                               : (var_l > 0 ? 0.0 : 1.0);
    auto result = p < 1e-3 ? testing::AssertionSuccess() : testing::AssertionFailure();
    return result << what << ": F = " << var_l << " / " << var_s << " with (" << d_l << ", " << d_s
                  << ") degrees of freedom, p = " << p;
}

double chi_square_p_value(double statistic, double dof) {
    return boost::math::gamma_q(dof / 2, statistic / 2);
}

testing::AssertionResult chi_square_test(const std::string& what,
                                         const std::vector<double>& observed,
                                         const std::vector<double>& expected, int comparisons) {
    if (observed.size() != expected.size()) {
        return testing::AssertionFailure() << what << ": " << observed.size() << " cells observed, "
                                           << expected.size() << " expected";
    }
    constexpr double kMinExpected = 5;
    double statistic = 0, pooled_observed = 0, pooled_expected = 0;
    int cells = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < kMinExpected) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooled_expected > 0) {
        statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                     pooled_expected;
        ++cells;
    } else if (pooled_observed > 0) {
        return testing::AssertionFailure()
               << what << ": " << pooled_observed << " samples where none are expected";
    }
    const double dof = cells - 1, p = chi_square_p_value(statistic, dof);
    const double level = 1e-3 / comparisons;
    std::ostringstream msg;
    msg << what << ": chi-square " << statistic << " on " << dof << " degrees of freedom, p = " << p
        << (p >= level ? " >= " : " < ") << level;
    return p >= level ? testing::AssertionSuccess() << msg.str()
                      : testing::AssertionFailure() << msg.str();
}

}  // namespace hmcr::test
