// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: solution files (.vtp) as `render`, `info` and `study` read them.
//
// Input: the bytes of a .vtp. Whatever read_vtp returns must be a mesh the renderer can use:
// polygons naming existing points, one value per point and per cell, the cells in a solution's
// order (fronts patch by patch, then backs), cluster ids only with clustering and in range, and
// on a higher-order basis the coordinates, coefficients and leaf of every point and cell.
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"
#include "viz/vtk_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const auto vtp = write("fuzz.vtp", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        hmcr::VtpMetadata meta;
        const hmcr::ShadedMesh m = hmcr::read_vtp(vtp, &meta);
        const std::size_t cells = m.cell_count();
        if (m.point_radiosity.size() != m.points.size()) crash("radiosity per point");
        if (m.element_radiosity.size() != cells || m.patch_id.size() != cells ||
            m.element_area.size() != cells || m.hierarchy_level.size() != cells) {
            crash("a value per cell is missing");
        }
        for (std::int64_t id : m.connectivity) {
            if (id < 0 || std::size_t(id) >= m.points.size()) crash("a cell names a missing point");
        }
        for (int p : m.patch_id) {
            if (p < 0 || std::uint64_t(p) >= meta.patch_count) crash("a PatchId out of range");
        }
        for (std::size_t c = 1; c < cells; ++c) {  // fronts patch by patch, then backs
            if (m.side[c] < m.side[c - 1] ||
                (m.side[c] == m.side[c - 1] && m.patch_id[c] < m.patch_id[c - 1])) {
                crash("cells out of their order");
            }
        }
        if (m.basis == hmcr::Basis::constant) {
            if (!m.leaf_coordinates.empty() || !m.coefficients.empty() || !m.leaf_index.empty()) {
                crash("higher-order arrays on the constant basis");
            }
        } else {
            if (m.leaf_coordinates.size() != m.points.size()) crash("coordinates per point");
            if (m.coefficients.size() != m.cell_stride() * cells) crash("coefficients per cell");
            if (m.leaf_index.size() != cells) crash("a leaf per cell");
            for (const hmcr::Vec2& ab : m.leaf_coordinates) {
                if (!(ab.minCoeff() >= 0 && ab.maxCoeff() <= 1)) crash("coordinates outside");
            }
            for (std::size_t c = 0; c < cells; ++c) {
                const auto corners = m.offsets[c + 1] - m.offsets[c];
                if (corners != 3 && corners != 4) crash("a sub-cell of neither shape");
                const std::int32_t before = c == 0 ? -1 : m.leaf_index[c - 1];
                if (m.leaf_index[c] != before && m.leaf_index[c] != before + 1) {
                    crash("a leaf's cells apart");
                }
            }
            if (m.leaf_count() != meta.element_count) crash("leaves, not the elements recorded");
        }
        if (!m.cluster_id.empty() && meta.clustering != "isotropic") crash("ids, no clustering");
        for (std::int32_t id : m.cluster_id) {
            if (id < -1 || std::int64_t(id) >= 2 * std::int64_t(meta.patch_count) - 1) {
                crash("a ClusterId out of range");
            }
        }
    });
    return 0;
}
