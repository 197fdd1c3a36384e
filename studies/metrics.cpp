// SPDX-License-Identifier: Apache-2.0
#include "studies/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "image/tone_map.h"
#include "studies/table_fields.h"

namespace hmcr {
namespace {

constexpr double kEqualWeights[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};

void check_same_size(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size() ||
        a.pixels.empty() || a.pixels.size() != std::size_t(a.width) * std::size_t(a.height)) {
        throw std::invalid_argument(
            "images to compare must have the same non-empty size: " + std::to_string(a.width) +
            " x " + std::to_string(a.height) + " and " + std::to_string(b.width) + " x " +
            std::to_string(b.height));
    }
}

// sqrt of the mean over pixels of sum_c w_c (a_c - b_c)^2.
double weighted_rmse(const Image8& a, const Image8& b, const double (&w)[3]) {
    check_same_size(a, b);
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels[i][c]) - double(b.pixels[i][c]);
            sum += w[c] * d * d;
        }
    }
    return std::sqrt(sum / double(a.pixels.size()));
}

}  // namespace

double rmse_a(const Image8& a, const Image8& b) { return weighted_rmse(a, b, kEqualWeights); }

double rmse_p(const Image8& a, const Image8& b) { return weighted_rmse(a, b, kLuminanceWeights); }

ErrorSplit split_error(const std::vector<Image8>& images, const Image8& reference) {
    if (images.size() < 2) throw std::invalid_argument("split_error needs two images or more");
    const double k = double(images.size());
    double mse_single = 0;  // mean over the images
    for (const Image8& im : images) {
        const double e = weighted_rmse(im, reference, kLuminanceWeights);
        mse_single += e * e / k;
    }
    double sum = 0;  // squared error of the images' mean
    for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            double mean = 0;
            for (const Image8& im : images) mean += double(im.pixels[i][c]) / k;
            const double d = mean - double(reference.pixels[i][c]);
            sum += kLuminanceWeights[c] * d * d;
        }
    }
    const double mse_mean = sum / double(reference.pixels.size());
    const double bias2 = (k * mse_mean - mse_single) / (k - 1);
    return {std::sqrt(std::max(0.0, bias2)), std::sqrt(std::max(0.0, mse_single - bias2))};
}

double psnr(double rmse) {
    if (rmse == 0) return std::numeric_limits<double>::infinity();
    return 20 * std::log10(255 / rmse);
}

ImageErrors image_errors(const Image8& solution, const Image8& reference) {
    ImageErrors e;
    e.rmse_a = rmse_a(solution, reference);
    e.rmse_p = rmse_p(solution, reference);
    e.psnr_a = psnr(e.rmse_a);
    e.psnr_p = psnr(e.rmse_p);
    return e;
}

std::string ImageErrors::to_string() const {
    std::ostringstream s;
    s << "ImageErrors{rmse_a=" << rmse_a << ", rmse_p=" << rmse_p << ", psnr_a=" << psnr_a
      << ", psnr_p=" << psnr_p << "}";
    return s.str();
}

void to_json(nlohmann::json& j, const ImageErrors& e) {
    j = {{"rmse_a", e.rmse_a}, {"rmse_p", e.rmse_p}, {"psnr_a", e.psnr_a}, {"psnr_p", e.psnr_p}};
}

void from_json(const nlohmann::json& j, ImageErrors& e) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    e = {json_non_negative(j, "rmse_a", kNaN), json_non_negative(j, "rmse_p", kNaN),
         json_non_negative(j, "psnr_a", kInf), json_non_negative(j, "psnr_p", kInf)};
}

}  // namespace hmcr
