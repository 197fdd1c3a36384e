// SPDX-License-Identifier: Apache-2.0
#include "information/leaf_patches.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace hmcr {
namespace {

// The polygon's corners: points where the boundary turns (collinear points dropped).
std::vector<Vec3> corners(const ShadedMesh& m, std::size_t cell) {
    const auto first = m.offsets[cell], n = m.offsets[cell + 1] - first;
    auto at = [&](std::int64_t k) { return m.points[m.connectivity[first + (k % n + n) % n]]; };
    std::vector<Vec3> out;
    for (std::int64_t k = 0; k < n; ++k) {
        const Vec3 a = at(k - 1), b = at(k), c = at(k + 1);
        const double turn = (b - a).cross(c - b).norm();
        if (turn > 1e-9 * (b - a).norm() * (c - b).norm()) out.push_back(b);
    }
    return out;
}

}  // namespace

PatchSet leaf_patches(const ShadedMesh& mesh) {
    PatchSet set;
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
        const std::vector<Vec3> k = corners(mesh, c);
        if (k.size() < 3 || k.size() > 4) {
            throw std::invalid_argument("cell " + std::to_string(c) + " has " +
                                        std::to_string(k.size()) + " corners, not 3 or 4");
        }
        Patch p;
        p.corner_count = std::uint8_t(k.size());
        for (std::size_t i = 0; i < k.size(); ++i) p.corner[i] = k[i];
        p.finalize();
        set.total_area += p.area;
        set.patches.push_back(p);
    }
    return set;
}

}  // namespace hmcr
