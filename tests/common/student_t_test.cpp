// SPDX-License-Identifier: Apache-2.0
// The tests' own Student t quantiles (tests/support/statistics.h) against published values.
#include <gtest/gtest.h>

#include <array>

#include "tests/support/statistics.h"

namespace hmcr::test {
namespace {

TEST(StudentT, QuantilesMatchThePublishedTwoSidedTable) {
    // Two-sided 0.999 quantiles for 1..30 degrees of freedom (standard tables), each within
    // half a unit of its last printed digit: the table's own rounding.
    constexpr std::array<double, 30> kT = {
        636.62, 31.599, 12.924, 8.610, 6.869, 5.959, 5.408, 5.041, 4.781, 4.587,
        4.437,  4.318,  4.221,  4.140, 4.073, 4.015, 3.965, 3.922, 3.883, 3.850,
        3.819,  3.792,  3.768,  3.745, 3.725, 3.707, 3.690, 3.674, 3.659, 3.646};
    for (std::size_t k = 0; k < kT.size(); ++k) {
        const double half_unit = k == 0 ? 5e-3 : 5e-4;
        EXPECT_NEAR(student_quantile(1e-3, double(k + 1)), kT[k], half_unit) << k + 1;
    }
    // 0.95 two-sided: 12.706 (1 dof), 2.131 (15), 2.042 (30); 1.960 in the normal limit.
    EXPECT_NEAR(student_quantile(0.05, 1), 12.706, 5e-4);
    EXPECT_NEAR(student_quantile(0.05, 15), 2.131, 5e-4);
    EXPECT_NEAR(student_quantile(0.05, 30), 2.042, 5e-4);
    EXPECT_NEAR(student_quantile(0.05, 1e6), 1.960, 5e-4);
    EXPECT_NEAR(student_p_value(0, 15), 1.0, 1e-12);
}

}  // namespace
}  // namespace hmcr::test
