// The tests' own Student t quantiles (tests/support/statistics.h) against published values.
#include <gtest/gtest.h>

#include <array>

#include "tests/support/statistics.h"

namespace hmcr::test {
namespace {

TEST(StudentT, QuantilesMatchThePublishedTwoSidedTable) {
    // Two-sided 0.999 quantiles for 1..30 degrees of freedom (standard tables).
    constexpr std::array<double, 30> kT = {
        636.62, 31.599, 12.924, 8.610, 6.869, 5.959, 5.408, 5.041, 4.781, 4.587,
        4.437,  4.318,  4.221,  4.140, 4.073, 4.015, 3.965, 3.922, 3.883, 3.850,
        3.819,  3.792,  3.768,  3.745, 3.725, 3.707, 3.690, 3.674, 3.659, 3.646};
    for (std::size_t k = 0; k < kT.size(); ++k) {
        EXPECT_NEAR(student_quantile(1e-3, double(k + 1)), kT[k], 6e-4 * kT[k]) << k + 1;
    }
    // 0.95 two-sided: 12.706 (1 dof), 2.131 (15), 2.042 (30).
    EXPECT_NEAR(student_quantile(0.05, 1), 12.706, 1e-3);
    EXPECT_NEAR(student_quantile(0.05, 15), 2.131, 1e-3);
    EXPECT_NEAR(student_quantile(0.05, 30), 2.042, 1e-3);
    EXPECT_NEAR(student_p_value(0, 15), 1.0, 1e-12);
}

}  // namespace
}  // namespace hmcr::test
