// SPDX-License-Identifier: Apache-2.0
// The point-to-point form factor kernel of docs/design.md §4, without visibility:
// F(x, y) = max(0, cos theta_x) max(0, cos theta_y) / (pi r^2).
#pragma once

#include <numbers>

#include "common/types.h"

namespace hmcr {

inline double point_kernel(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny) {
    const Vec3 d = y - x;
    const double r2 = d.squaredNorm();
    const double cx = nx.dot(d), cy = -ny.dot(d);
    if (cx <= 0 || cy <= 0 || r2 == 0) return 0;
    return cx * cy / (std::numbers::pi * r2 * r2);  // the two cosines carry a factor r each
}

}  // namespace hmcr
