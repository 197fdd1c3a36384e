// SPDX-License-Identifier: Apache-2.0
// Basic numeric types of the engine.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products everywhere
#include <bit>
#include <cstdint>

namespace hmcr {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec2f = Eigen::Vector2f;  // parameter points of rays and elements in single precision
using Rgb = Eigen::Array3d;     // radiometric triple, one value per channel

// |c| of docs/design.md §3: the sum of the channels.
inline double channel_sum(const Rgb& c) { return c.sum(); }

// Whether v is a subnormal number (nonzero, below 2.2e-308 in size), told by its bits: every
// thread that traces rays flushes such numbers to 0 (rays/embree_scene.h), where a comparison
// would take them for 0 too. Settings refuse them rather than compute with a 0 they exclude.
inline bool is_subnormal(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    return (bits & 0x7ff0000000000000ULL) == 0 && (bits & 0x000fffffffffffffULL) != 0;
}

// "5e-324 is a subnormal number, ...": why such a value is refused.
inline constexpr const char* kSubnormalReason =
    "is a subnormal number, which hmcr's ray tracing computes as 0 (the smallest normal "
    "number is 2.2e-308)";

}  // namespace hmcr
