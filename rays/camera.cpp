// SPDX-License-Identifier: Apache-2.0
#include "rays/camera.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hmcr {

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

}  // namespace hmcr
