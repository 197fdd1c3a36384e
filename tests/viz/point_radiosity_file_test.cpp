// SPDX-License-Identifier: Apache-2.0
// A point reference's points.vtp reads back as written, and a damaged one is refused naming the
// file; another program's solution is read from its polygons, Radiosity and PatchId alone.
#include "viz/point_radiosity_file.h"

#include <gtest/gtest.h>

#include <limits>

#include "common/error.h"
#include "tests/support/shaded_scenes.h"
#include "tests/support/temp_dir.h"
#include "viz/foreign_solution.h"
#include "viz/vtk_export.h"

namespace hmcr::test {
namespace {

PointRadiosity three_points() {
    PointRadiosity r;
    r.points = {{Vec3(0.1, 0.2, 0), 0.25, 0, kFront},
                {Vec3(0.6, 0.7, 0), 0.25, 1, kFront},
                {Vec3(0.6, 0.7, 0), 0.25, 1, kBack}};
    r.radiosity[0] = {Rgb(1, 2, 3), Rgb(0.5, 0.25, 0.125), Rgb::Zero()};
    r.radiosity[1] = {Rgb(1.5, 2, 3), Rgb(0.5, 0.75, 0.125), Rgb::Zero()};
    r.variance[0] = {Rgb(0.01, 0.02, 0.03), Rgb::Zero(), Rgb::Zero()};
    r.variance[1] = {Rgb(0.02, 0.02, 0.03), Rgb::Constant(1e-9), Rgb::Zero()};
    r.paths = 64;
    r.seed = 7;
    r.scene = "two";
    r.geometry_hash = "0123456789abcdef";
    r.patch_count = 2;
    return r;
}

void expect_refused(const std::filesystem::path& file, const std::string& needle) {
    try {
        read_point_radiosity(file);
        ADD_FAILURE() << "accepted " << needle;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

TEST(PointRadiosityFile, ReadsBackWhatWasWritten) {
    TempDir dir;
    const PointRadiosity r = three_points();
    write_point_radiosity(dir.path() / "p.vtp", r);
    const PointRadiosity back = read_point_radiosity(dir.path() / "p.vtp");
    EXPECT_EQ(back.paths, 64u);
    EXPECT_EQ(back.seed, 7u);
    EXPECT_EQ(back.scene, "two");
    EXPECT_EQ(back.geometry_hash, r.geometry_hash);
    EXPECT_EQ(back.patch_count, 2u);
    ASSERT_EQ(back.points.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(back.points[i].position == r.points[i].position);
        EXPECT_EQ(back.points[i].weight, r.points[i].weight);
        EXPECT_EQ(back.points[i].patch, r.points[i].patch);
        EXPECT_EQ(back.points[i].side, r.points[i].side);
        for (int s = 0; s < 2; ++s) {
            EXPECT_TRUE((back.radiosity[s][i] == r.radiosity[s][i]).all());  // float64: exact
            EXPECT_TRUE((back.variance[s][i] == r.variance[s][i]).all());
        }
    }
}

TEST(PointRadiosityFile, RefusesWhatNoReferenceHolds) {
    TempDir dir;
    const auto spoiled = [&](const char* name, auto&& spoil) {
        PointRadiosity r = three_points();
        spoil(r);
        write_point_radiosity(dir.path() / name, r);
        return dir.path() / name;
    };
    expect_refused(spoiled("patch.vtp", [](PointRadiosity& r) { r.points[1].patch = 2; }),
                   "PatchId 2, but the scene has 2 patches");
    expect_refused(spoiled("side.vtp", [](PointRadiosity& r) { r.points[1].side = 2; }),
                   "Side 2, not 0 or 1");
    expect_refused(spoiled("weight.vtp", [](PointRadiosity& r) { r.points[0].weight = 0; }),
                   "has Weight 0");
    expect_refused(spoiled("variance.vtp", [](PointRadiosity& r) { r.variance[1][0][2] = -1; }),
                   "Variance2 -1 is negative");
    expect_refused(spoiled("nan.vtp",
                           [](PointRadiosity& r) {
                               r.radiosity[0][1][0] = std::numeric_limits<double>::quiet_NaN();
                           }),
                   "Radiosity1");
    expect_refused(spoiled("paths.vtp", [](PointRadiosity& r) { r.paths = 0; }), "Paths is 0");
    expect_refused(dir.write("junk.vtp", "<VTKFile>"), "junk.vtp");
    expect_refused(dir.path() / "none.vtp", "no such file");
}

// An hmcr solution holds what a foreign one needs: read as foreign it is the same field.
TEST(ForeignSolution, AnHmcrSolutionReadsAsTheSameField) {
    MeshHierarchy s(two_quads(true));
    s.at(0, {1, 2});
    s.for_leaves(0, [&](Element& e) { e.radiosity = Rgb(1, 2, 3) * (1 + e.centre.x()); });
    const ShadedMesh m = s.shade();
    TempDir dir;
    VtpMetadata meta;
    meta.patch_count = 2;
    meta.element_count = m.cell_count();
    write_vtp(dir.path() / "m.vtp", m, meta);
    const ShadedMesh f = read_foreign_solution(dir.path() / "m.vtp", 2);
    EXPECT_EQ(f.offsets, m.offsets);
    EXPECT_EQ(f.connectivity, m.connectivity);
    EXPECT_EQ(f.patch_id, m.patch_id);
    for (std::size_t i = 0; i < m.points.size(); ++i) {
        EXPECT_TRUE(f.point_radiosity[i].isApprox(m.point_radiosity[i], 1e-6));
    }
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        EXPECT_NEAR(f.element_area[c], m.element_area[c], 1e-12);
    }
    try {
        read_foreign_solution(dir.path() / "m.vtp", 1);
        ADD_FAILURE() << "a PatchId beyond the scene was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("PatchId 1, but the scene has 1 patches"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace hmcr::test
