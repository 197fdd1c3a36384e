#include "tests/support/statistics.h"

#include <array>
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

testing::AssertionResult t_test(const std::string& what, const std::vector<double>& samples,
                                double expected, double bias_bound) {
    // Two-sided 0.999 quantiles of Student's t for 1..30 degrees of freedom.
    static constexpr std::array<double, 30> kT = {
        636.62, 31.599, 12.924, 8.610, 6.869, 5.959, 5.408, 5.041, 4.781, 4.587,
        4.437,  4.318,  4.221,  4.140, 4.073, 4.015, 3.965, 3.922, 3.883, 3.850,
        3.819,  3.792,  3.768,  3.745, 3.725, 3.707, 3.690, 3.674, 3.659, 3.646};
    const Estimate e = estimate_mean(samples);
    if (e.n < 2 || e.n > kT.size() + 1) return testing::AssertionFailure() << "t_test needs 2..31";
    return within_standard_errors(what + " (t test, " + std::to_string(e.n) + " runs)", e.mean,
                                  expected, e.standard_error, bias_bound, kT[e.n - 2]);
}

}  // namespace hmcr::test
