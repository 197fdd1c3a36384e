// SPDX-License-Identifier: Apache-2.0
// Shaded meshes built in code for the object-error tests: unit-square grids carrying a field.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "radiosity/shaded_mesh.h"
#include "rays/patch.h"

namespace hmcr::test {

using Field = std::function<Rgb(const Vec3&)>;

// The unit square [0,1]^2 at height z as an nx x ny grid of cells of one patch, quads or (when
// `triangles`) each quad cut along its diagonal, counter-clockwise seen from +z unless
// `facing_down`.
inline ShadedMesh grid(int nx, int ny, const Field& field, bool triangles = false, double z = 0,
                       int patch = 0, bool facing_down = false) {
    ShadedMesh m;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            m.points.emplace_back(double(i) / nx, double(j) / ny, z);
            m.point_radiosity.push_back(field(m.points.back()));
        }
    }
    const auto add_cell = [&](std::vector<std::int64_t> c) {
        if (facing_down) std::reverse(c.begin(), c.end());
        m.connectivity.insert(m.connectivity.end(), c.begin(), c.end());
        m.offsets.push_back(std::int64_t(m.connectivity.size()));
        m.patch_id.push_back(patch);
        m.side.push_back(kFront);
        m.element_area.push_back(1.0 / (double(nx) * ny) / (triangles ? 2 : 1));
    };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const std::int64_t a = j * (nx + 1) + i, b = a + 1, c = b + nx + 1, d = a + nx + 1;
            if (triangles) {
                add_cell({a, b, c});
                add_cell({a, c, d});
            } else {
                add_cell({a, b, c, d});
            }
        }
    }
    return m;
}

// `part` appended to `into`, its points and cells renumbered.
inline void append(ShadedMesh& into, const ShadedMesh& part) {
    const auto base = std::int64_t(into.points.size());
    into.points.insert(into.points.end(), part.points.begin(), part.points.end());
    into.point_radiosity.insert(into.point_radiosity.end(), part.point_radiosity.begin(),
                                part.point_radiosity.end());
    for (std::size_t c = 0; c < part.cell_count(); ++c) {
        for (auto s = part.offsets[c]; s < part.offsets[c + 1]; ++s) {
            into.connectivity.push_back(base + part.connectivity[s]);
        }
        into.offsets.push_back(std::int64_t(into.connectivity.size()));
        into.patch_id.push_back(part.patch_id[c]);
        if (c < part.side.size()) into.side.push_back(part.side[c]);
        if (c < part.element_area.size()) into.element_area.push_back(part.element_area[c]);
    }
}

}  // namespace hmcr::test
