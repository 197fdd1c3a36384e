// SPDX-License-Identifier: Apache-2.0
// Deposits in whole quanta of power (docs/design.md §9). Each ray's deposit is rounded to
// a quantum and summed as an integer; integer sums are exact in any order, so the threads of one
// process and the ranks of an MPI run may add them in any order and still get the same bits.
#pragma once

#include <array>
#include <cstdint>

#include "common/types.h"

namespace hmcr {

using Quanta = std::array<std::int64_t, 3>;  // per channel

// std::int64_t(std::floor(x)) for |x| < 2^63, without a call into the maths library (hmcr is
// built for the baseline x86-64, which has no rounding instruction): truncated toward zero, then
// one down if that is above x. At |x| >= 2^52 x is an integer and the truncation exact.
inline std::int64_t floor_to_int(double x) {
    const auto t = std::int64_t(x);
    return double(t) > x ? t - 1 : t;
}

// The quantum of one iteration, per channel, sized so that the iteration's whole power fits in
// 2^61 quanta: no sum can overflow (rounding adds less than a quantum per ray), and a ray
// carries up to 2^61 / N quanta (8.6e11 at 2.68 M rays, 2.3e8 at 10^10). Rounding is dithered
// by a uniform number of the ray's own stream, so it is unbiased: rays of equal power (all
// those of one source element) would otherwise all round the same way, a bias of up to half
// a quantum per ray that exceeds the noise beyond about 10^13 rays per iteration.
struct PowerQuantum {
    Rgb watts = Rgb::Zero();  // the power of one quantum; 0 in a channel no ray carries

    // `ray_power_bound`: no ray of the iteration carries more power than this in a channel.
    static PowerQuantum for_iteration(const Rgb& ray_power_bound, std::uint64_t rays) {
        return {ray_power_bound * (double(rays) / 0x1p61)};
    }
    // `dither` in [0, 1): rounds down with probability 1 - frac(power / watts).
    Quanta count(const Rgb& power, double dither) const {
        Quanta q{};
        for (int c = 0; c < 3; ++c) {
            q[c] = watts[c] > 0 ? floor_to_int(power[c] / watts[c] + dither) : 0;
        }
        return q;
    }
    Rgb power(const Quanta& q) const {
        return {double(q[0]) * watts[0], double(q[1]) * watts[1], double(q[2]) * watts[2]};
    }
};

inline void add(Quanta& sum, const Quanta& q) {
    for (int c = 0; c < 3; ++c) sum[c] += q[c];
}

}  // namespace hmcr
