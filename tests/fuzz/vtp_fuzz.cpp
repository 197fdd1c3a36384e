// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: solution files (.vtp) as `render`, `info` and `study` read them.
//
// Input: the bytes of a .vtp. Whatever read_vtp returns must be a mesh the renderer can use:
// polygons naming existing points, one value per point and per cell, the cells in a solution's
// order (fronts patch by patch, then backs), cluster ids only with clustering and in range.
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
        if (!m.cluster_id.empty() && meta.clustering != "isotropic") crash("ids, no clustering");
        for (std::int32_t id : m.cluster_id) {
            if (id < -1 || std::int64_t(id) >= 2 * std::int64_t(meta.patch_count) - 1) {
                crash("a ClusterId out of range");
            }
        }
    });
    return 0;
}
