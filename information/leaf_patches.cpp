// SPDX-License-Identifier: Apache-2.0
#include "information/leaf_patches.h"

#include <algorithm>
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

// The corners of the leaf whose cells are [first, last): its points at local coordinates
// (0, 0), (1, 0), (1, 1), (0, 1) (a quad's, cells of 4 points) or (0, 0), (1, 0), (0, 1), in the
// order its cells run (a back's reversed).
std::vector<Vec3> leaf_corners(const ShadedMesh& m, std::size_t first, std::size_t last) {
    const bool quad = m.offsets[first + 1] - m.offsets[first] == 4;
    const std::vector<Vec2> want = quad ? std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}
                                        : std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}};
    std::vector<Vec3> out(want.size());
    std::vector<bool> found(want.size(), false);
    for (auto s = m.offsets[first]; s < m.offsets[last]; ++s) {
        const auto point = std::size_t(m.connectivity[std::size_t(s)]);
        for (std::size_t k = 0; k < want.size(); ++k) {
            if (m.leaf_coordinates[point] == want[k]) {
                out[k] = m.points[point];
                found[k] = true;
            }
        }
    }
    if (std::find(found.begin(), found.end(), false) != found.end()) {
        throw std::invalid_argument("the leaf of cell " + std::to_string(first) +
                                    " has no point at a corner of its domain");
    }
    if (!m.side.empty() && m.side[first] == kBack) std::reverse(out.begin(), out.end());
    return out;
}

}  // namespace

std::vector<std::size_t> leaf_first_cells(const ShadedMesh& mesh) {
    std::vector<std::size_t> first;
    first.reserve(mesh.leaf_count());
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
        if (mesh.leaf_index.empty() || c == 0 || mesh.leaf_index[c] != mesh.leaf_index[c - 1]) {
            first.push_back(c);
        }
    }
    return first;
}

PatchSet leaf_patches(const ShadedMesh& mesh) {
    PatchSet set;
    const std::vector<std::size_t> first = leaf_first_cells(mesh);
    for (std::size_t l = 0; l < first.size(); ++l) {
        const std::size_t c = first[l];
        const std::vector<Vec3> k =
            mesh.leaf_index.empty()
                ? corners(mesh, c)
                : leaf_corners(mesh, c, l + 1 < first.size() ? first[l + 1] : mesh.cell_count());
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
