// SPDX-License-Identifier: Apache-2.0
#include "viz/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "image/tone_map.h"
#include "rays/camera.h"
#include "viz/mesh_colors.h"

namespace hmcr {
namespace {

Rgb pixel_radiance(const ShadedTracer& tracer, const Camera& camera, int x, int y, int n) {
    Rgb sum = Rgb::Zero();
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Vec3 d = camera.direction(x + (i + 0.5) / n, y + (j + 0.5) / n);
            if (const auto b = tracer.radiosity_along(camera.origin, d)) sum += *b;
        }
    }
    return sum / (std::numbers::pi * n * n);  // L = B / pi, averaged over the samples
}

}  // namespace

std::string RenderOptions::to_string() const {
    return "RenderOptions{samples_per_axis=" + std::to_string(samples_per_axis) + "}";
}

Image render(const ShadedMesh& mesh, const View& view, const RenderOptions& options) {
    return render(ShadedTracer(mesh), view, options);
}

Image render(const ShadedTracer& tracer, const View& view, const RenderOptions& options) {
    if (options.samples_per_axis < 1) {
        throw std::invalid_argument("samples_per_axis must be at least 1: " + options.to_string());
    }
    const Camera camera = make_camera(view);
    Image image(view.width, view.height);
    // Every pixel depends only on its own rays, so the split into tasks cannot change the image.
    tbb::parallel_for(
        tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& rows) {
            set_tracing_float_mode();
            for (int y = rows.begin(); y < rows.end(); ++y) {
                for (int x = 0; x < view.width; ++x) {
                    image.at(x, y) = pixel_radiance(tracer, camera, x, y, options.samples_per_axis);
                }
            }
        });
    return image;
}

Image8 draw_cell_edges(const ShadedTracer& tracer, const View& view, Image8 image, Srgb8 ink) {
    if (image.width != view.width || image.height != view.height) {
        throw std::invalid_argument("draw_cell_edges: the image is not of the view's size");
    }
    const Camera camera = make_camera(view);
    constexpr std::int64_t kNone = -1;
    std::vector<std::int64_t> cells(image.pixels.size(), kNone);
    tbb::parallel_for(
        tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& rows) {
            set_tracing_float_mode();
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = 0; x < view.width; ++x) {
                    const auto c =
                        tracer.cell_along(camera.origin, camera.direction(x + 0.5, y + 0.5));
                    cells[std::size_t(y) * view.width + x] = c ? std::int64_t(*c) : kNone;
                }
        });
    const auto cell = [&](int x, int y) { return cells[std::size_t(y) * view.width + x]; };
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
            const std::int64_t c = cell(x, y);
            const bool right = x + 1 < view.width && cell(x + 1, y) != c;
            const bool below = y + 1 < view.height && cell(x, y + 1) != c;
            if (right || below) image.at(x, y) = ink;
        }
    return image;
}

double exposure_from(const Image& reference) {
    double sum = 0;
    std::size_t count = 0;
    for (const Rgb& p : reference.pixels) {
        const double y = luminance(p);
        if (y > 0) {
            sum += y;
            ++count;
        }
    }
    if (count == 0) return 1.0;
    return kMiddleGrey / (sum / double(count));
}

}  // namespace hmcr
