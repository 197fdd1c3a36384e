// SPDX-License-Identifier: Apache-2.0
// CIE chromaticities to RGB for the MGF reader (see mgf_color.h for the conversion chosen).
#include "meshes/mgf_color.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace hmcr {
namespace {

// One lobe of the Wyman-Sloan-Shirley fit: a Gaussian with a different width on each side.
double lobe(double l, double mean, double below, double above) {
    const double t = (l - mean) / (l < mean ? below : above);
    return std::exp(-0.5 * t * t);
}

// Integration step and range (nm): the matching functions vanish outside 360-830 nm.
constexpr double kStep = 1.0;
constexpr double kFirst = 360.0, kLast = 830.0;

std::optional<Chromaticity> from_xyz(const Eigen::Vector3d& xyz) {
    const double sum = xyz.sum();
    if (!(sum > 0) || !(xyz.y() > 0) || !std::isfinite(sum)) return std::nullopt;
    return Chromaticity{xyz.x() / sum, xyz.y() / sum};
}

// The largest magnitude of `values`: a chromaticity does not see a common factor, so sums are
// taken of the values divided by it, which cannot overflow (a spectrum of 1e308 everywhere).
template <class Range, class Value>
double largest(const Range& values, Value&& value) {
    double m = 0;
    for (const auto& v : values) m = std::max(m, std::abs(value(v)));
    return m;
}

// log(e^x - 1) for x > 0, without overflow where e^x does (x > 709).
double log_expm1(double x) {
    return x > 30 ? x + std::log1p(-std::exp(-x)) : std::log(std::expm1(x));
}

// XYZ of a chromaticity at luminance Y.
Eigen::Vector3d to_xyz(const Chromaticity& c, double luminance) {
    return {c.x / c.y * luminance, luminance, (1 - c.x - c.y) / c.y * luminance};
}

// XYZ -> RGB from the primaries and the white point (the usual derivation: the primaries'
// XYZ at unit luminance, scaled so that they add up to the white's XYZ).
Eigen::Matrix3d xyz_to_rgb() {
    const Chromaticity primaries[3] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    Eigen::Matrix3d p;
    for (int i = 0; i < 3; ++i) p.col(i) = to_xyz(primaries[i], 1.0);
    const Eigen::Vector3d scale = p.inverse() * to_xyz(Chromaticity{}, 1.0);
    return (p * scale.asDiagonal()).inverse();
}

}  // namespace

Eigen::Vector3d cie_matching(double nanometres) {
    const double x = 1.056 * lobe(nanometres, 599.8, 37.9, 31.0) +
                     0.362 * lobe(nanometres, 442.0, 16.0, 26.7) -
                     0.065 * lobe(nanometres, 501.1, 20.4, 26.2);
    const double y =
        0.821 * lobe(nanometres, 568.8, 46.9, 40.5) + 0.286 * lobe(nanometres, 530.9, 16.3, 31.1);
    const double z =
        1.217 * lobe(nanometres, 437.0, 11.8, 36.0) + 0.681 * lobe(nanometres, 459.0, 26.0, 13.8);
    return {x, y, z};
}

std::optional<Chromaticity> spectrum_chromaticity(double lmin, double lmax,
                                                  const std::vector<double>& values) {
    if (values.size() < 2 || !(lmax > lmin)) return std::nullopt;
    const double intervals = double(values.size() - 1);
    const double spacing = lmax / intervals - lmin / intervals;  // lmax - lmin may overflow
    const double scale = largest(values, [](double v) { return v; });
    if (!(scale > 0) || !std::isfinite(spacing)) return std::nullopt;
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (double l = std::max(kFirst, lmin); l <= std::min(kLast, lmax); l += kStep) {
        const double at = (l - lmin) / spacing;
        const std::size_t i = std::min(std::size_t(at), values.size() - 2);
        const double t = at - double(i);
        xyz += ((1 - t) * values[i] / scale + t * values[i + 1] / scale) * cie_matching(l);
    }
    return from_xyz(xyz);
}

std::optional<Chromaticity> blackbody_chromaticity(double kelvin) {
    if (!(kelvin > 0)) return std::nullopt;
    // Below 1 K the band's radiance is its longest wavelength's alone, in double precision (the
    // next is e^-16000 times smaller): the colour of every colder body, whose exponents would
    // overflow.
    kelvin = std::max(kelvin, 1e-3);
    constexpr double c2 = 1.438777e-2;  // second radiation constant h c / k, m K
    // Planck's law up to a constant factor, which the chromaticity does not see, in logarithms:
    // the radiance itself overflows or underflows far from everyday temperatures (1e300 K, whose
    // colour is the Rayleigh-Jeans limit's), its ratio to the largest over the band does not.
    std::vector<double> log_radiance;
    for (double l = kFirst; l <= kLast; l += kStep) {
        const double metres = l * 1e-9;
        log_radiance.push_back(-5 * std::log(metres) - log_expm1(c2 / (metres * kelvin)));
    }
    const double top = *std::max_element(log_radiance.begin(), log_radiance.end());
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    std::size_t i = 0;
    for (double l = kFirst; l <= kLast; l += kStep) {
        xyz += std::exp(log_radiance[i++] - top) * cie_matching(l);
    }
    return from_xyz(xyz);
}

std::optional<Chromaticity> mix_chromaticity(
    const std::vector<std::pair<double, Chromaticity>>& parts) {
    const double scale = largest(parts, [](const auto& part) { return part.first; });
    if (!(scale > 0)) return std::nullopt;
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (const auto& [weight, c] : parts) {
        if (!(weight >= 0)) return std::nullopt;
        xyz += to_xyz(c, weight / scale);
    }
    return from_xyz(xyz);
}

Eigen::Vector3d chromaticity_rgb(const Chromaticity& c, double luminance) {
    static const Eigen::Matrix3d m = xyz_to_rgb();
    return m * to_xyz(c, luminance);
}

double rgb_luminance(const Eigen::Vector3d& rgb) {
    static const Eigen::Matrix3d m = xyz_to_rgb().inverse();
    return m.row(1).dot(rgb);
}

}  // namespace hmcr
