// Basic numeric types of the engine.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products everywhere

namespace hmcr {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec2f = Eigen::Vector2f;  // parameter points of rays and elements in single precision
using Rgb = Eigen::Array3d;     // radiometric triple, one value per channel

// |c| of docs/design.md §3: the sum of the channels.
inline double channel_sum(const Rgb& c) { return c.sum(); }

}  // namespace hmcr
