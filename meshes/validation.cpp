// SPDX-License-Identifier: Apache-2.0
// Patch and material validation. The tolerances are relative to the face's own size so that
// the checks mean the same in a 5 cm model and a 50 m hall.
#include "meshes/validation.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace hmcr {
namespace {

// The turn at corner i: cross product of the incoming and outgoing edge. Its length is twice
// the area of the corner triangle; for a planar polygon it is parallel to the face normal.
Eigen::Vector3d corner_turn(const std::vector<Eigen::Vector3d>& p, std::size_t i) {
    const std::size_t n = p.size();
    const Eigen::Vector3d& prev = p[(i + n - 1) % n];
    const Eigen::Vector3d& next = p[(i + 1) % n];
    return (p[i] - prev).cross(next - p[i]);
}

std::optional<std::string> check_repeated(const std::vector<int>& ids) {
    for (std::size_t i = 0; i < ids.size(); ++i) {
        for (std::size_t j = i + 1; j < ids.size(); ++j) {
            if (ids[i] == ids[j]) {
                return fmt::format("degenerate face: corners {} and {} are the same point", i + 1,
                                   j + 1);
            }
        }
    }
    return std::nullopt;
}

// Zero area (triangle) or a corner collinear with its neighbours (quad).
std::optional<std::string> check_area(const std::vector<Eigen::Vector3d>& p) {
    const double edge = largest_edge(p);
    const double limit = kDegenerateAreaRatio * edge * edge;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double area = 0.5 * corner_turn(p, i).norm();
        if (!std::isfinite(area) || !std::isfinite(limit)) {
            return std::string("face too large: its size overflows double precision");
        }
        if (area < limit) {
            return fmt::format(
                "degenerate face: corner {} spans an area of {:.3g} m^2, below {:g} x (largest "
                "edge {:.3g} m)^2",
                i + 1, area, kDegenerateAreaRatio, edge);
        }
    }
    return std::nullopt;
}

// Distance of the 4th corner from the plane of the first three, and the tolerance for it.
std::pair<double, double> off_plane(const std::vector<Eigen::Vector3d>& p) {
    const Eigen::Vector3d normal = corner_turn(p, 1).normalized();
    const double distance = std::abs((p[3] - p[0]).dot(normal));
    const double diagonal = std::max((p[2] - p[0]).norm(), (p[3] - p[1]).norm());
    return {distance, kPlanarityRatio * diagonal};
}

std::optional<std::string> check_planar(const std::vector<Eigen::Vector3d>& p) {
    const auto [distance, tolerance] = off_plane(p);
    if (distance <= tolerance) return std::nullopt;
    return fmt::format(
        "non-planar quad: the 4th vertex is {:.3g} mm off the plane of the other three "
        "(tolerance {:.3g} mm = {:g} x diagonal); split it into two triangles",
        1e3 * distance, 1e3 * tolerance, kPlanarityRatio);
}

// Every corner must turn the same way. The reference is the corner with the largest turn
// rather than the face normal, which vanishes for a symmetric bow-tie.
std::optional<std::string> check_convex(const std::vector<Eigen::Vector3d>& p) {
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Eigen::Vector3d turn = corner_turn(p, i);
        if (turn.squaredNorm() > reference.squaredNorm()) reference = turn;
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (corner_turn(p, i).dot(reference) <= 0) {
            return fmt::format(
                "non-convex quad: corner {} turns the other way; split it into two triangles",
                i + 1);
        }
    }
    return std::nullopt;
}

// `bound` is the first value out of range, described by `bound_text`.
std::optional<std::string> check_channels(const Material& m, const Eigen::Vector3d& value,
                                          const char* what, double bound, const char* bound_text) {
    for (int c = 0; c < 3; ++c) {
        const double v = value[c];
        if (std::isnan(v) || v >= bound) {
            return fmt::format("{} {} of material {} is {}", what, v, quote(m.name), bound_text);
        }
        if (v < 0) return fmt::format("{} {} of material {} is negative", what, v, quote(m.name));
    }
    return std::nullopt;
}

}  // namespace

double largest_edge(const std::vector<Eigen::Vector3d>& corners) {
    double longest = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        longest = std::max(longest, (corners[(i + 1) % corners.size()] - corners[i]).norm());
    }
    return longest;
}

std::optional<std::string> check_position(const Eigen::Vector3d& p) {
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(p[c]) <= kMaxCoordinate)) {
            return fmt::format(
                "coordinate {:g} is out of range: hmcr reads positions within +-{:g} m (its ray "
                "tracer computes in single precision)",
                p[c], kMaxCoordinate);
        }
    }
    return std::nullopt;
}

bool quad_is_planar(const std::vector<Eigen::Vector3d>& corners) {
    const auto [distance, tolerance] = off_plane(corners);
    return distance <= tolerance;
}

std::optional<std::string> check_face_geometry(const std::vector<Eigen::Vector3d>& corners,
                                               const std::vector<int>& ids) {
    if (corners.size() > 4) {
        return fmt::format(
            "polygon with {} vertices: --strict reads triangles and convex quads "
            "only (without it hmcr triangulates the polygon)",
            corners.size());
    }
    if (auto error = check_repeated(ids)) return error;
    if (auto error = check_area(corners)) return error;
    if (corners.size() != 4) return std::nullopt;
    if (auto error = check_planar(corners)) return error;
    return check_convex(corners);
}

FaceKey face_key(const std::vector<int>& ids) {
    constexpr int kNone = std::numeric_limits<int>::max();
    FaceKey key{kNone, kNone, kNone, kNone};
    std::copy_n(ids.begin(), std::min<std::size_t>(ids.size(), 4), key.begin());
    std::sort(key.begin(), key.end());
    return key;
}

// Sorting (key, face) pairs finds every group of equal keys; the answer is the group whose
// second face comes first, as a scan in face order would meet it.
std::optional<std::pair<std::size_t, std::size_t>> find_duplicate_face(
    const std::vector<FaceKey>& faces) {
    std::vector<std::uint32_t> order(faces.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return key_order(faces[a], a, faces[b], b);
    });
    std::optional<std::pair<std::size_t, std::size_t>> first;
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (!same_key(faces[order[k]], faces[order[k - 1]])) continue;
        // order[k - 1] is the group's first face when order[k] is its second
        if (k >= 2 && same_key(faces[order[k - 2]], faces[order[k]])) continue;
        if (!first || order[k] < first->first) first = std::make_pair(order[k], order[k - 1]);
    }
    return first;
}

std::optional<std::string> check_reflectance(const Material& m, bool allow_one) {
    if (allow_one) {
        return check_channels(m, m.kd, "reflectance", std::nextafter(1.0, 2.0), "above 1");
    }
    return check_channels(m, m.kd, "reflectance", 1.0, "not below 1");
}

std::optional<std::string> check_specular(const Material& m, bool allow_one) {
    if (auto error = check_channels(m, m.ks, "specular reflectance", INFINITY, "not finite"))
        return error;
    if (!(m.roughness >= 0 && m.roughness <= kMaxRoughness)) {
        return fmt::format(
            "roughness {} of material {} is out of range: hmcr reads 0 (a mirror) "
            "to {:g}",
            m.roughness, quote(m.name), kMaxRoughness);
    }
    const Eigen::Vector3d total = m.kd + m.ks;
    if (allow_one) {
        return check_channels(m, total, "diffuse + specular reflectance", std::nextafter(1.0, 2.0),
                              "above 1");
    }
    return check_channels(m, total, "diffuse + specular reflectance", 1.0, "not below 1");
}

std::optional<std::string> check_emission(const Material& m) {
    return check_channels(m, m.ke, "emission", kMaxRadiance,
                          fmt::format("not below {:g} W/(sr m^2)", kMaxRadiance).c_str());
}

}  // namespace hmcr
