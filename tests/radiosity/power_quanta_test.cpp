// SPDX-License-Identifier: Apache-2.0
#include "radiosity/power_quanta.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rays/rng.h"

namespace hmcr::test {
namespace {

// floor_to_int is the maths library's floor as an integer wherever the quanta need it (|x| below
// 2^63): both signs, integers and their neighbours, fractions, and every magnitude up to 2^62.
TEST(PowerQuanta, FloorToIntIsTheFloor) {
    std::vector<double> xs = {0.0,
                              -0.0,
                              0.5,
                              -0.5,
                              1.0,
                              -1.0,
                              0x1p52,
                              0x1p52 + 1,
                              0x1p53,
                              0x1p62,
                              -0x1p62,
                              0x1p52 - 0.5,
                              -(0x1p52 - 0.5),
                              1e-300,
                              -1e-300};
    for (const double n : {1.0, 2.0, 3.0, 1e6, 0x1p40, 0x1p51}) {
        for (const double sign : {1.0, -1.0}) {
            xs.push_back(sign * n);
            xs.push_back(std::nextafter(sign * n, 0.0));
            xs.push_back(std::nextafter(sign * n, sign * 0x1p63));
        }
    }
    Rng rng(12, 0);
    for (int k = 0; k < 100'000; ++k) {
        const double magnitude = std::ldexp(rng.uniform(), int(rng.uniform() * 64) - 1);
        xs.push_back(rng.uniform() < 0.5 ? magnitude : -magnitude);
    }
    for (const double x : xs) {
        ASSERT_EQ(floor_to_int(x), std::int64_t(std::floor(x))) << x;
    }
}

}  // namespace
}  // namespace hmcr::test
