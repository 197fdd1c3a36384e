// CIE chromaticities to RGB for the MGF reader (see mgf_color.h for the conversion chosen).
#include "meshes/mgf_color.h"

#include <Eigen/LU>
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
    if (!(sum > 0) || !(xyz.y() > 0)) return std::nullopt;
    return Chromaticity{xyz.x() / sum, xyz.y() / sum};
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

Eigen::Vector3d cie_matching(double l) {
    const double x = 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                     0.065 * lobe(l, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8);
    return {x, y, z};
}

std::optional<Chromaticity> spectrum_chromaticity(double lmin, double lmax,
                                                  const std::vector<double>& values) {
    if (values.size() < 2 || !(lmax > lmin)) return std::nullopt;
    const double spacing = (lmax - lmin) / double(values.size() - 1);
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (double l = std::max(kFirst, lmin); l <= std::min(kLast, lmax); l += kStep) {
        const double at = (l - lmin) / spacing;
        const std::size_t i = std::min(std::size_t(at), values.size() - 2);
        const double t = at - double(i);
        xyz += ((1 - t) * values[i] + t * values[i + 1]) * cie_matching(l);
    }
    return from_xyz(xyz);
}

std::optional<Chromaticity> blackbody_chromaticity(double kelvin) {
    if (!(kelvin > 0)) return std::nullopt;
    constexpr double c2 = 1.438777e-2;  // second radiation constant h c / k, m K
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (double l = kFirst; l <= kLast; l += kStep) {
        const double metres = l * 1e-9;
        // Planck's law up to a constant factor, which the chromaticity does not see.
        const double radiance = 1.0 / (std::pow(metres, 5) * std::expm1(c2 / (metres * kelvin)));
        xyz += radiance * cie_matching(l);
    }
    return from_xyz(xyz);
}

std::optional<Chromaticity> mix_chromaticity(
    const std::vector<std::pair<double, Chromaticity>>& parts) {
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (const auto& [weight, c] : parts) {
        if (!(weight >= 0)) return std::nullopt;
        xyz += to_xyz(c, weight);
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
