// SPDX-License-Identifier: Apache-2.0
// Validation of loaded patches and materials (docs/design.md §1), on plain numbers so that it can
// be tested without files. Each check returns the message of the first problem (without the
// `file:line:` prefix, which the caller knows) or nothing.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "meshes/scene.h"

namespace hmcr {

// Relative tolerances of the geometric checks.
inline constexpr double kDegenerateAreaRatio = 1e-12;  // area / (largest edge)^2 below: zero
inline constexpr double kPlanarityRatio = 1e-4;        // off-plane distance / diagonal above
// Emitted radiance above this is refused: the sun's is about 2e7 W/(sr m^2), and far larger
// values overflow the sums of power into infinities (a solve that never ends).
inline constexpr double kMaxRadiance = 1e20;
// A corner with a coordinate beyond this (metres, either sign) is refused: the ray tracer
// (Embree) computes in single precision, where a product of three lengths overflows (3.4e38)
// from about 7e12 m. A scene scaled by 1e13 already solves differently from the same scene at
// 1e12; by 1e15 no ray finds the light.
inline constexpr double kMaxCoordinate = 1e12;
// The largest roughness (RMS facet slope) of a glossy lobe: MGF calls values above 0.2 unusual,
// and the Gaussian facet model means little once facets tilt by 45 degrees on average.
inline constexpr double kMaxRoughness = 1;

// The longest edge of a closed polygon: the length the degeneracy tolerances are relative to.
double largest_edge(const std::vector<Eigen::Vector3d>& corners);

// Whether the 4th corner of a quad lies within kPlanarityRatio x its longer diagonal of the plane
// of the other three.
bool quad_is_planar(const std::vector<Eigen::Vector3d>& corners);

// The message for a position with a coordinate beyond kMaxCoordinate, or nothing.
std::optional<std::string> check_position(const Eigen::Vector3d& p);

// Checks one polygon given by its corners (counter-clockwise, welded: equal positions are the
// same index in `ids`): 3 or 4 distinct corners, no zero-area corner, and for a quad planarity
// and convexity. (Without --strict the repairs have made every polygon pass.)
std::optional<std::string> check_face_geometry(const std::vector<Eigen::Vector3d>& corners,
                                               const std::vector<int>& ids);

// A checked face's (welded) vertex ids, sorted, INT_MAX after the last: equal for two faces on the
// same vertices whatever their order or orientation.
using FaceKey = std::array<int, 4>;
FaceKey face_key(const std::vector<int>& ids);  // 3 or 4 ids

// Equality, and the order of (key, index) pairs, spelled out: std::array's operators call
// memcmp, which was most of the time of sorting a million keys.
inline bool same_key(const FaceKey& a, const FaceKey& b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
}
inline bool key_order(const FaceKey& a, std::uint32_t i, const FaceKey& b, std::uint32_t j) {
    return std::tie(a[0], a[1], a[2], a[3], i) < std::tie(b[0], b[1], b[2], b[3], j);
}

// Finds the first face that uses the same set of (welded) vertices as an earlier one.
// Returns {later face, earlier face}.
std::optional<std::pair<std::size_t, std::size_t>> find_duplicate_face(
    const std::vector<FaceKey>& faces);

// Checks Kd in [0, 1) (or [0, 1] when allow_one) and Ke in [0, kMaxRadiance) per channel;
// names the material.
std::optional<std::string> check_reflectance(const Material& m, bool allow_one = false);
std::optional<std::string> check_emission(const Material& m);
// Checks Ks not negative, the roughness in [0, kMaxRoughness] and Kd + Ks in [0, 1) (or [0, 1]
// when allow_one) per channel: a surface reflects at most what it receives.
std::optional<std::string> check_specular(const Material& m, bool allow_one = false);

}  // namespace hmcr
