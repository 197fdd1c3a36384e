// SPDX-License-Identifier: Apache-2.0
// Exact form factors of docs/design.md §8 (standard configuration-factor catalogue formulas).
#pragma once

#include <cmath>
#include <numbers>

namespace hmcr::test {

// Directly opposed parallel rectangles a x b at distance c.
inline double parallel_rectangles(double a, double b, double c) {
    const double x = a / c, y = b / c, pi = std::numbers::pi;
    const double x2 = x * x, y2 = y * y;
    return 2 / (pi * x * y) *
           (std::log(std::sqrt((1 + x2) * (1 + y2) / (1 + x2 + y2))) +
            x * std::sqrt(1 + y2) * std::atan(x / std::sqrt(1 + y2)) +
            y * std::sqrt(1 + x2) * std::atan(y / std::sqrt(1 + x2)) - x * std::atan(x) -
            y * std::atan(y));
}

// From a w x l rectangle to a perpendicular h x l rectangle sharing the edge of length l.
inline double perpendicular_rectangles(double l, double w, double h) {
    const double W = w / l, H = h / l, pi = std::numbers::pi;
    const double W2 = W * W, H2 = H * H, s = std::sqrt(W2 + H2);
    const double a = (1 + W2) * (1 + H2) / (1 + W2 + H2);
    const double b = std::pow(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2)), W2);
    const double c = std::pow(H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2)), H2);
    return 1 / (pi * W) *
           (W * std::atan(1 / W) + H * std::atan(1 / H) - s * std::atan(1 / s) +
            0.25 * std::log(a * b * c));
}

// Differential area at height h below the centre of (and parallel to) an a x b rectangle.
inline double point_to_centred_rectangle(double a, double b, double h) {
    const double x = a / (2 * h), y = b / (2 * h), pi = std::numbers::pi;
    // Four corner rectangles of the classic differential-to-corner formula.
    const double one = 1 / (2 * pi) *
                       (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                        y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
    return 4 * one;
}

// From a differential area to a parallel rectangle [x0, x1] x [y0, y1] (coordinates relative
// to the foot of the point's normal) at distance h: the signed sum of the four rectangles
// that have a corner at the foot.
inline double point_to_parallel_rectangle(double x0, double x1, double y0, double y1, double h) {
    auto corner = [h](double x, double y) {
        const double X = x / h, Y = y / h, pi = std::numbers::pi;
        const double sx = std::sqrt(1 + X * X), sy = std::sqrt(1 + Y * Y);
        return 1 / (2 * pi) * (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy));
    };
    return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

}  // namespace hmcr::test
