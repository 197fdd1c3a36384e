// SPDX-License-Identifier: Apache-2.0
// join_fan_quads (fan_quads.h).
#include "meshes/fan_quads.h"

#include "meshes/validation.h"

namespace hmcr {
namespace {

bool is_fan_quad(const std::array<std::uint32_t, 3>& t, const std::array<std::uint32_t, 3>& u,
                 const std::vector<Eigen::Vector3d>& positions) {
    if (t[0] != u[0] || t[2] != u[1]) return false;
    const std::vector<Eigen::Vector3d> corners{positions[t[0]], positions[t[1]], positions[t[2]],
                                               positions[u[2]]};
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t j = i + 1; j < 4; ++j) {
            if (corners[i] == corners[j]) return false;
        }
    }
    return !check_face_geometry(corners, {0, 1, 2, 3});
}

}  // namespace

void join_fan_quads(std::span<const std::array<std::uint32_t, 3>> triangles,
                    const std::vector<Eigen::Vector3d>& positions,
                    const std::function<void(std::span<const std::uint32_t>)>& polygon) {
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        const auto& t = triangles[k];
        if (k + 1 < triangles.size() && is_fan_quad(t, triangles[k + 1], positions)) {
            const std::array<std::uint32_t, 4> quad{t[0], t[1], t[2], triangles[k + 1][2]};
            polygon(quad);
            ++k;
        } else {
            polygon(t);
        }
    }
}

}  // namespace hmcr
