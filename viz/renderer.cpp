#include "viz/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "viz/tone_map.h"

namespace hmcr {
namespace {

// The pinhole camera's orthonormal frame, scaled so that image-plane coordinates in [-1, 1]
// span the field of view.
struct Camera {
    Vec3 origin, forward, right, up;  // right and up carry tan(fov / 2) and the aspect ratio
    int width = 0, height = 0;

    // Unit direction through the image-plane point (px, py), in pixels from the top left.
    Vec3 direction(double px, double py) const {
        const double sx = 2 * px / width - 1, sy = 1 - 2 * py / height;
        return (forward + sx * right + sy * up).normalized();
    }
};

Camera make_camera(const View& view) {
    const std::string where = "view '" + view.name + "': ";
    if (view.width <= 0 || view.height <= 0) {
        throw std::invalid_argument(where + "image size must be positive");
    }
    if (!(view.fov_degrees > 0 && view.fov_degrees < 180)) {
        throw std::invalid_argument(where + "fov must be in (0, 180) degrees");
    }
    const Vec3 to_target = view.look_at - view.position;
    if (!(to_target.norm() > 0)) throw std::invalid_argument(where + "position is the look_at");
    const Vec3 forward = to_target.normalized();
    const Vec3 side = forward.cross(view.up);
    // Relative test: up within ~1e-6 rad of the viewing direction leaves no usable frame.
    if (!(side.norm() > 1e-6 * view.up.norm())) {
        throw std::invalid_argument(where + "up is parallel to the viewing direction");
    }
    const Vec3 right = side.normalized(), up = right.cross(forward);
    const double half_height = std::tan(view.fov_degrees * std::numbers::pi / 360);
    const double aspect = double(view.width) / view.height;
    return {view.position,    forward,    aspect * half_height * right,
            half_height * up, view.width, view.height};
}

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
