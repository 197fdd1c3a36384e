// SPDX-License-Identifier: Apache-2.0
// Image metrics of a meshing study (docs/design.md §6), on 8-bit sRGB images on the 0-255 scale,
// both quantised with the one exposure the study fixed from its reference.
//
//   RMSEa = sqrt( (1 / 3N) sum_pixels sum_channels (a_c - b_c)^2 )       channels weighted equally
//   RMSEp = sqrt( (1 / N) sum_pixels sum_channels w_c (a_c - b_c)^2 )    w = 0.2126, 0.7152, 0.0722
//   PSNR  = 20 log10(255 / RMSE), for each
//
// The weights of RMSEp are the Rec. 709 luminance coefficients (they sum to 1, so a uniform
// error e in every channel gives RMSEa = RMSEp = e). Identical images have RMSE 0 and PSNR +inf
// (the limit, and what keeps "higher is better" true); a study table prints it as "inf".
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "image/image.h"

namespace hmcr {

struct ImageErrors {
    double rmse_a = 0, rmse_p = 0;  // 0-255 scale
    double psnr_a = 0, psnr_p = 0;  // dB; +inf when the RMSE is 0

    std::string to_string() const;
};
// {"rmse_a", "rmse_p", "psnr_a", "psnr_p"}: how references and study cells store them. An
// infinite PSNR is written as null (JSON has no inf) and read back as +inf, a null RMSE as NaN.
void to_json(nlohmann::json& j, const ImageErrors& e);
void from_json(const nlohmann::json& j, ImageErrors& e);

// Throws std::invalid_argument when the images differ in size or are empty.
double rmse_a(const Image8& a, const Image8& b);
double rmse_p(const Image8& a, const Image8& b);
double psnr(double rmse);  // 20 log10(255 / rmse); +inf for 0
ImageErrors image_errors(const Image8& solution, const Image8& reference);

// The RMSEp of k >= 2 images of one estimator (k seeds) split into its two parts, on the
// 0-255 scale: with bias the RMS of the expected image's difference from the reference and
// noise the RMS of an image's standard deviation,
//   E[MSE of one image]        = bias^2 + noise^2
//   E[MSE of the images' mean] = bias^2 + noise^2 / k,
// solved with the measured MSEs (each part clamped at 0). The bias includes the reference's
// own noise and the 8-bit rounding, shared by every estimator measured against it.
struct ErrorSplit {
    double bias = 0, noise = 0;
};
ErrorSplit split_error(const std::vector<Image8>& images, const Image8& reference);

}  // namespace hmcr
