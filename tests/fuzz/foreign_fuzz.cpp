// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: another program's solution (.vtp) as `hmcr error --foreign` reads it.
//
// Input: the bytes of a .vtp. Whatever read_foreign_solution returns must be a mesh the
// object error and the renderer can use: polygons naming existing points, a finite radiosity
// per point, patch ids below the patch count given, sides 0 or 1.
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"
#include "viz/foreign_solution.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    constexpr std::uint64_t kPatches = 64;
    const auto vtp = write("foreign.vtp", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        const hmcr::ShadedMesh m = hmcr::read_foreign_solution(vtp, kPatches);
        const std::size_t cells = m.cell_count();
        if (m.point_radiosity.size() != m.points.size()) crash("radiosity per point");
        if (m.patch_id.size() != cells || m.side.size() != cells ||
            m.element_area.size() != cells || m.element_radiosity.size() != cells) {
            crash("a value per cell is missing");
        }
        for (std::int64_t id : m.connectivity) {
            if (id < 0 || std::size_t(id) >= m.points.size()) crash("a cell names a missing point");
        }
        for (std::size_t c = 0; c < cells; ++c) {
            if (m.patch_id[c] < 0 || std::uint64_t(m.patch_id[c]) >= kPatches || m.side[c] > 1) {
                crash("a PatchId or Side out of range");
            }
        }
        for (const hmcr::Rgb& b : m.point_radiosity) {
            if (!b.isFinite().all() || !(b >= 0).all()) crash("a radiosity that cannot be");
        }
    });
    return 0;
}
