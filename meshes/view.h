// SPDX-License-Identifier: Apache-2.0
// A view of a scene: a pinhole camera (rays/camera.h) and its image size, as a scene file
// gives it (docs/design.md §11.1).
#pragma once

#include <Eigen/Core>
#include <string>

namespace hmcr {

struct View {
    std::string name;
    Eigen::Vector3d position{0, 0, 0};
    Eigen::Vector3d look_at{0, 0, 1};
    Eigen::Vector3d up{0, 1, 0};
    double fov_degrees = 40;  // vertical field of view
    int width = 512;
    int height = 512;
};

}  // namespace hmcr
