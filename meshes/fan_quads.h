// SPDX-License-Identifier: Apache-2.0
// Quads that a format of triangles only (glTF) holds as the two triangles (a b c) and (a c d) of a
// fan, as Blender's exporter splits them, joined back into the quad (a b c d) where it is a
// planar convex quad (docs/decisions.md: quads stay quads).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace hmcr {

// Calls polygon(corners) for every polygon of the triangles (three indices into positions a
// triangle, in order): a triangle and the next one that are (a b c), (a c d) of a planar convex
// quad (meshes/validation.h's checks, on four distinct positions) become one call with (a b c
// d), every other triangle a call of its own.
void join_fan_quads(std::span<const std::array<std::uint32_t, 3>> triangles,
                    const std::vector<Eigen::Vector3d>& positions,
                    const std::function<void(std::span<const std::uint32_t>)>& polygon);

}  // namespace hmcr
