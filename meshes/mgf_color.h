// SPDX-License-Identifier: Apache-2.0
// MGF colours (cxy, cspec, cct, cmix) reduced to the linear RGB hmcr computes in.
//
// Every MGF colour is kept as a CIE 1931 (x, y) chromaticity: a spectrum (cspec, cct) is
// integrated against the CIE 1931 2-degree colour matching functions, and a mix (cmix) adds the
// colours' XYZ with Y = its weight (cmix weights are relative luminances). The luminance comes
// from the statement that uses the colour (rd: photometric reflectance, ed: emittance), so that
// XYZ = (x/y Y, Y, (1-x-y)/y Y). XYZ goes to linear RGB with the Rec. 709 (sRGB) primaries and
// MGF's own white, equal energy (x = y = 1/3; the MGF specification's application notes
// recommend that white point): MGF's default neutral grey is R = G = B = Y.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace hmcr {

struct Chromaticity {
    double x = 1.0 / 3;  // MGF's default: equal-energy grey
    double y = 1.0 / 3;
};

// CIE 1931 2-degree colour matching functions (x-bar, y-bar, z-bar) at a wavelength in nm, by
// the multi-lobe Gaussian fit of Wyman, Sloan and Shirley, "Simple analytic approximations to
// the CIE XYZ color matching functions", JCGT 2(2), 2013 (within about 1% of the tables).
Eigen::Vector3d cie_matching(double nanometres);

// The chromaticity of a spectrum sampled evenly from lmin to lmax nm (zero outside), of values of
// any finite size; nothing when it has no visible energy or a negative XYZ sum.
std::optional<Chromaticity> spectrum_chromaticity(double lmin, double lmax,
                                                  const std::vector<double>& values);

// The chromaticity of a black body at the temperature (kelvin, > 0): any finite temperature
// has one, the limits included (a red at the band's end below 1 K, the Rayleigh-Jeans blue
// above 10^9 K); nothing for one not above 0.
std::optional<Chromaticity> blackbody_chromaticity(double kelvin);

// The chromaticity of colours mixed by relative luminance weights (>= 0, not all 0).
std::optional<Chromaticity> mix_chromaticity(
    const std::vector<std::pair<double, Chromaticity>>& parts);

// Linear RGB (Rec. 709 primaries, equal-energy white) of a colour of luminance Y. Channels
// outside the RGB gamut can come out negative; the caller decides.
Eigen::Vector3d chromaticity_rgb(const Chromaticity& c, double luminance);

// The luminance Y of a linear RGB colour (the inverse of chromaticity_rgb's).
double rgb_luminance(const Eigen::Vector3d& rgb);

}  // namespace hmcr
