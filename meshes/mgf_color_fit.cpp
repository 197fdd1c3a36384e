// SPDX-License-Identifier: Apache-2.0
#include "meshes/mgf_color_fit.h"

#include <algorithm>

namespace hmcr {

FittedColour fit_colour(const Chromaticity& c, double luminance, double upper) {
    const Eigen::Vector3d grey = Eigen::Vector3d::Constant(luminance);
    if (c.x == 1.0 / 3 && c.y == 1.0 / 3) return {grey, false};
    const Eigen::Vector3d out = chromaticity_rgb(c, luminance);
    if (c.y == 0 || !out.allFinite()) return {grey, true};  // no luminance, or x / y overflows
    double t = 1;                                           // how much of the colour is kept
    for (int k = 0; k < 3; ++k) {
        if (out[k] < 0) t = std::min(t, luminance / (luminance - out[k]));
        if (out[k] > upper) t = std::min(t, (upper - luminance) / (out[k] - luminance));
    }
    if (t == 1) return {out, false};
    return {(grey + t * (out - grey)).cwiseMax(0.0).cwiseMin(upper), true};
}

std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> fit_sum(const Eigen::Vector3d& kd,
                                                                   double rd,
                                                                   const Eigen::Vector3d& ks,
                                                                   double rs) {
    const double luminance = rd + rs;
    const double upper = std::min(std::max(luminance, kMaxColouredReflectance), 1.0);
    const Eigen::Vector3d total = kd + ks;
    if (luminance > 1 || total.maxCoeff() <= upper) return std::nullopt;
    double t = 1;  // how much of the colours is kept
    for (int k = 0; k < 3; ++k) {
        if (total[k] > upper) t = std::min(t, (upper - luminance) / (total[k] - luminance));
    }
    const Eigen::Vector3d grey_d = Eigen::Vector3d::Constant(rd);
    const Eigen::Vector3d grey_s = Eigen::Vector3d::Constant(rs);
    if (t == 0) return std::pair(grey_d, grey_s);
    return std::pair(Eigen::Vector3d((grey_d + t * (kd - grey_d)).cwiseMax(0.0)),
                     Eigen::Vector3d((grey_s + t * (ks - grey_s)).cwiseMax(0.0)));
}

}  // namespace hmcr
