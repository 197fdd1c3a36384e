// SPDX-License-Identifier: Apache-2.0
// A solution read back from its .vtp is the mesh that was written (to float precision).
#include "viz/vtk_import.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/shaded_scenes.h"
#include "tests/support/temp_dir.h"
#include "viz/vtk_export.h"

namespace hmcr::test {
namespace {

TEST(VtkImport, ReadsBackWhatWasWritten) {
    MeshHierarchy s(two_quads(true));
    s.at(0, {1, 2});
    s.for_leaves(0, [&](Element& e) { e.radiosity = Rgb(1, 2, 3) * (1 + e.centre.x()); });
    const ShadedMesh m = s.shade();
    TempDir dir;
    VtpMetadata meta;
    meta.patch_count = 2;
    meta.element_count = m.cell_count();
    meta.scene = "two quads";
    meta.geometry_hash = "0123456789abcdef";
    write_vtp(dir.path() / "m.vtp", m, meta);
    VtpMetadata back;
    const ShadedMesh r = read_vtp(dir.path() / "m.vtp", &back);
    EXPECT_EQ(back.patch_count, 2u);
    EXPECT_EQ(back.scene, meta.scene);
    EXPECT_EQ(back.geometry_hash, meta.geometry_hash);
    ASSERT_EQ(r.points.size(), m.points.size());
    EXPECT_EQ(r.offsets, m.offsets);
    EXPECT_EQ(r.connectivity, m.connectivity);
    EXPECT_EQ(r.patch_id, m.patch_id);
    EXPECT_EQ(r.hierarchy_level, m.hierarchy_level);
    for (std::size_t i = 0; i < m.points.size(); ++i) {
        EXPECT_TRUE(r.points[i].isApprox(m.points[i], 1e-6));
        EXPECT_TRUE(r.point_radiosity[i].isApprox(m.point_radiosity[i], 1e-6));
    }
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        EXPECT_TRUE(r.element_radiosity[c].isApprox(m.element_radiosity[c], 1e-6));
        EXPECT_NEAR(r.element_area[c], m.element_area[c], 1e-12);
    }
}

TEST(VtkImport, NamesTheFileWhenItIsMissingOrNotASolution) {
    TempDir dir;
    try {
        read_vtp(dir.path() / "none.vtp");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("none.vtp: no such file"), std::string::npos);
    }
    const auto junk = dir.write("junk.vtp", "<VTKFile>nonsense");
    try {
        read_vtp(junk);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("junk.vtp"), std::string::npos);
    }
}

}  // namespace
}  // namespace hmcr::test
