// SPDX-License-Identifier: Apache-2.0
// The pinhole camera of a scene's View, shared by the radiosity renderer and the path tracer.
//
// A pinhole at View::position looking at View::look_at, with View::up made orthogonal to the
// viewing direction, View::fov_degrees the vertical field of view and the horizontal one
// following from the aspect ratio width / height. Pixel (x, y), y counted from the top row,
// covers [x, x + 1] x [y, y + 1] on the image plane.
#pragma once

#include "common/types.h"
#include "meshes/view.h"

namespace hmcr {

// The camera's orthonormal frame, scaled so that image-plane coordinates in [-1, 1] span the
// field of view.
struct Camera {
    Vec3 origin, forward, right, up;  // right and up carry tan(fov / 2) and the aspect ratio
    int width = 0, height = 0;

    // Unit direction through the image-plane point (px, py), in pixels from the top left.
    Vec3 direction(double px, double py) const {
        const double sx = 2 * px / width - 1, sy = 1 - 2 * py / height;
        return (forward + sx * right + sy * up).normalized();
    }
};

// Throws std::invalid_argument on a bad view: size, fov outside (0, 180), position at look_at,
// up along the viewing direction.
Camera make_camera(const View& view);

}  // namespace hmcr
