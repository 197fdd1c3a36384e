// SPDX-License-Identifier: Apache-2.0
// A solution read back from its .vtp is the mesh that was written (to float precision).
#include "viz/vtk_import.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "common/error.h"
#include "tests/support/shaded_scenes.h"
#include "tests/support/temp_dir.h"
#include "viz/shaded_tracer.h"
#include "viz/solution_file.h"
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

// A higher-order solution's arrays come back as written (doubles, bit for bit), a second write
// of what was read is the first's bytes, and the tracer evaluates the same values on both.
TEST(VtkImport, AHigherOrderSolutionRoundTrips) {
    for (const bool quads : {true, false}) {
        MeshHierarchy s(quads ? two_quads(false) : two_triangles());
        s.h->set_basis(Basis::cubic);
        s.at(0, {3, 2});
        s.at(1, {1});
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> term(-0.3, 0.3);
        s.h->for_each_leaf([&](const Element& e) {
            const_cast<Element&>(e).radiosity = Rgb(2, 3, 4) * (1 + e.centre.x());
            for (int k = 1; k < basis_size(Basis::cubic); ++k) {
                s.h->terms(e)[k - 1].radiosity = Rgb(term(rng), term(rng), term(rng));
            }
        });
        const ShadedMesh m = as_stored(s.shade());
        TempDir dir;
        VtpMetadata meta;
        meta.patch_count = 2;
        meta.element_count = s.h->leaf_count();
        meta.scene = "two patches";
        meta.geometry_hash = "0123456789abcdef";
        write_vtp(dir.path() / "first.vtp", m, meta);
        VtpMetadata back;
        const ShadedMesh r = read_vtp(dir.path() / "first.vtp", &back);
        EXPECT_EQ(r.basis, Basis::cubic);
        EXPECT_EQ(r.leaf_coordinates, m.leaf_coordinates);
        EXPECT_EQ(r.coefficients, m.coefficients);
        EXPECT_EQ(r.leaf_index, m.leaf_index);
        EXPECT_EQ(r.points, m.points);
        EXPECT_EQ(r.offsets, m.offsets);
        EXPECT_EQ(r.connectivity, m.connectivity);
        write_vtp(dir.path() / "second.vtp", r, back);
        EXPECT_EQ(read_file(dir.path() / "first.vtp"), read_file(dir.path() / "second.vtp"));
        const ShadedTracer written(m), read(r);
        std::uniform_real_distribution<double> at(0.01, 0.99);
        for (int k = 0; k < 200; ++k) {
            const Vec3 origin(at(rng), at(rng), 0.5), down(0, 0, -1);
            const auto a = written.hit_along(origin, down), b = read.hit_along(origin, down);
            ASSERT_EQ(bool(a), bool(b));
            if (!a) continue;
            EXPECT_EQ(a->cell, b->cell);
            EXPECT_TRUE((a->radiosity == b->radiosity).all());
        }
    }
}

// A constant solution's file holds none of the higher-order arrays.
TEST(VtkImport, AConstantSolutionHasNoBasisArrays) {
    MeshHierarchy s(two_quads(true));
    s.at(0, {1});
    const ShadedMesh m = s.shade();
    TempDir dir;
    VtpMetadata meta;
    meta.patch_count = 2;
    meta.element_count = m.cell_count();
    write_vtp(dir.path() / "m.vtp", m, meta);
    const std::string bytes = read_file(dir.path() / "m.vtp");
    for (const char* name : {"Basis", "LeafCoordinates", "Coefficients", "LeafIndex"}) {
        EXPECT_EQ(bytes.find(name), std::string::npos) << name;
    }
    EXPECT_EQ(read_vtp(dir.path() / "m.vtp").basis, Basis::constant);
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
