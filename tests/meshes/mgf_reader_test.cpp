// SPDX-License-Identifier: Apache-2.0
// The MGF reader: one test per entity (what it makes, and its errors with file:line), the
// transformations and arrays, includes, and the tessellation's stated area bound.
#include "meshes/mgf_reader.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <set>

#include "meshes/mgf_color.h"
#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;
constexpr double kPi = std::numbers::pi;

// A unit square in z = 0 facing +z, as MGF vertices q0..q3 (lines 1-8).
constexpr const char* kSquareVertices =
    "v q0 =\n p 0 0 0\nv q1 =\n p 1 0 0\nv q2 =\n p 1 1 0\nv q3 =\n p 0 1 0\n";

PolygonSoup read(const std::string& text, int segments = 24) {
    SceneFiles files;
    MgfOptions options;
    options.curve_segments = segments;
    return read_mgf(files.write("scene.mgf", text), options);
}

std::string read_error(const std::string& text) {
    return scene_error([&] { read(text); });
}

std::vector<Eigen::Vector3d> corners(const PolygonSoup& soup, std::size_t k) {
    std::vector<Eigen::Vector3d> out;
    for (std::uint32_t c : soup.corners(k)) out.push_back(soup.positions[c]);
    return out;
}

Eigen::Vector3d area_vector(const std::vector<Eigen::Vector3d>& p) {
    Eigen::Vector3d twice = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) twice += p[i].cross(p[(i + 1) % p.size()]);
    return 0.5 * twice;
}

double total_area(const PolygonSoup& soup) {
    double sum = 0;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k)
        sum += area_vector(corners(soup, k)).norm();
    return sum;
}

// The volume a closed surface encloses: positive when its polygons face outwards.
double signed_volume(const PolygonSoup& soup) {
    double sum = 0;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        const auto p = corners(soup, k);
        for (std::size_t i = 1; i + 1 < p.size(); ++i) sum += p[0].dot(p[i].cross(p[i + 1])) / 6;
    }
    return sum;
}

TEST(MgfReader, FaceOfNamedVertices) {
    const PolygonSoup soup = read(std::string(kSquareVertices) + "f q0 q1 q2 q3\n");
    ASSERT_EQ(soup.polygon_count(), 1u);
    EXPECT_EQ(corners(soup, 0)[2], Eigen::Vector3d(1, 1, 0));
    EXPECT_EQ(area_vector(corners(soup, 0)), Eigen::Vector3d(0, 0, 1));
    EXPECT_TRUE(contains(soup.where(soup.place[0]), "scene.mgf:9"));
    EXPECT_TRUE(contains(read_error(std::string(kSquareVertices) + "f q0 q1 nope\n"),
                         "scene.mgf:9: undefined name 'nope'"));
    EXPECT_TRUE(contains(read_error("f q0 q1\n"), "scene.mgf:1: 'f' needs at least 3 arguments"));
}

TEST(MgfReader, VertexContextsCopyAndReselect) {
    const std::string text = std::string(kSquareVertices) +
                             "v q4 = q2\n"       // a copy of q2 ...
                             "v q2\n p 5 5 5\n"  // ... keeps its own position when q2 moves
                             "f q0 q1 q4\n";
    const PolygonSoup soup = read(text);
    EXPECT_EQ(corners(soup, 0)[2], Eigen::Vector3d(1, 1, 0));
    EXPECT_TRUE(contains(read_error("p 1 2\n"), "scene.mgf:1: 'p' needs 3 to 3 arguments"));
    EXPECT_TRUE(contains(read_error("v a =\n p 1 x 3\n"), "scene.mgf:2: bad number 'x'"));
}

TEST(MgfReader, ObjectsNestAndMustBeOpenToEnd) {
    EXPECT_EQ(
        read(std::string(kSquareVertices) + "o room\no wall\nf q0 q1 q2\no\no\n").polygon_count(),
        1u);
    EXPECT_TRUE(contains(read_error("o a\no\no\n"), "scene.mgf:3: o ends no object"));
}

TEST(MgfReader, MaterialReflectanceEmissionAndSides) {
    const std::string text = std::string(kSquareVertices) +
                             "m paint =\n sides 1\n rd 0.5\nf q0 q1 q2\n"
                             "m lamp =\n ed 100\nf q0 q2 q3\n";
    const PolygonSoup soup = read(text);
    ASSERT_EQ(soup.materials.size(), 2u);
    EXPECT_EQ(soup.materials[0].material.kd, Eigen::Vector3d::Constant(0.5));
    EXPECT_EQ(soup.materials[0].material.name, "paint");
    EXPECT_TRUE(contains(soup.where(soup.materials[0].kd), "scene.mgf:11"));
    EXPECT_NEAR(soup.materials[1].material.ke.x(), 100 / kPi, 1e-12);  // E = pi Ke = ed
    EXPECT_TRUE(contains(soup.where(soup.materials[1].ke), "scene.mgf:14"));
    // `lamp` says nothing: two-sided, MGF's default.
    EXPECT_EQ(soup.materials[0].sides, 1);
    EXPECT_EQ(soup.materials[1].sides, 2);
    EXPECT_TRUE(soup.warnings.empty());
    EXPECT_TRUE(contains(read_error("m a =\n rd 1.5\n"), "scene.mgf:2: rd 1.5 is above 1"));
    EXPECT_TRUE(contains(read_error("m a =\n sides 3\n"), "scene.mgf:2: sides 3 is not 1 or 2"));
    EXPECT_TRUE(contains(read_error("m a =\n sides 0\n"), "scene.mgf:2: sides 0 is not 1 or 2"));
    EXPECT_TRUE(contains(read_error("m nope\n"), "scene.mgf:1: undefined name 'nope'"));
}

// Transmission and refraction are ignored with one warning; specular reflection (rs) is read
// (tests/meshes/specular_materials_test.cpp).
TEST(MgfReader, TransmissionStatementsAreIgnoredWithOneWarning) {
    const PolygonSoup soup = read(std::string(kSquareVertices) +
                                  "m glass =\n sides 1\n rs 0.1 0\n ts 0.8 0\n td 0.1\n ir 1.5 0\n"
                                  " ts 0.2 0\nf q0 q1 q2\n");
    ASSERT_EQ(soup.warnings.size(), 1u);
    const std::string& w = soup.warnings[0];
    EXPECT_TRUE(contains(w, "ts 2 times (first at"));
    EXPECT_TRUE(contains(w, "scene.mgf:12)"));
    for (const char* e : {"td 1 time", "ir 1 time"}) EXPECT_TRUE(contains(w, e));
    EXPECT_FALSE(contains(w, "rs 1 time"));
}

TEST(MgfReader, UnknownEntitiesAreSkippedWithAWarning) {
    const PolygonSoup soup = read(std::string(kSquareVertices) + "sphh q0 1\nf q0 q1 q2\n");
    EXPECT_EQ(soup.polygon_count(), 1u);
    ASSERT_FALSE(soup.warnings.empty());
    EXPECT_TRUE(contains(soup.warnings[0], "unknown entity 'sphh' 1 time (first at"));
}

// Colours: the conversion of mgf_color.h, checked on what is known exactly.
TEST(MgfReader, ColoursBecomeRgbAtTheirLuminance) {
    const std::string text = std::string(kSquareVertices) +
                             "c red =\n cxy 0.64 0.33\n"  // the Rec. 709 red primary
                             "m a =\n c red\n rd 0.1\nf q0 q1 q2\n"
                             "m b =\n c\n rd 0.4\nf q0 q2 q3\n";  // `c`: neutral grey again
    const PolygonSoup soup = read(text);
    const Eigen::Vector3d red = soup.materials[0].material.kd;
    EXPECT_GT(red.x(), 0.1);
    EXPECT_NEAR(red.y(), 0, 1e-12);
    EXPECT_NEAR(red.z(), 0, 1e-12);
    EXPECT_EQ(soup.materials[1].material.kd, Eigen::Vector3d::Constant(0.4));
    EXPECT_TRUE(contains(read_error("c a =\n cxy 0.8 0.5\n"), "scene.mgf:2: cxy: needs"));
}

// A colour outside the RGB gamut is read and fitted: its warning says so, apart from the
// statements hmcr ignores.
TEST(MgfReader, AColourFitIsNotAmongTheIgnoredStatements) {
    const PolygonSoup soup = read(std::string(kSquareVertices) +
                                  "c green =\n cxy 0.1 0.8\n"  // far outside Rec. 709
                                  "m a =\n c green\n rd 0.3\n ts 0.1 0\nf q0 q1 q2\n");
    ASSERT_EQ(soup.warnings.size(), 2u);
    EXPECT_TRUE(contains(soup.warnings[0],
                         "scene.mgf: 1 colour moved toward the grey of its luminance to fit RGB "
                         "(first at "))
        << soup.warnings[0];
    EXPECT_TRUE(contains(soup.warnings[0], "scene.mgf:13)")) << soup.warnings[0];
    EXPECT_TRUE(contains(soup.warnings[1],
                         "ignored (hmcr reads reflection rd and rs and emission "
                         "ed): ts 1 time"))
        << soup.warnings[1];
    EXPECT_FALSE(contains(soup.warnings[1], "colour")) << soup.warnings[1];
}

TEST(MgfReader, SpectraBlackBodiesAndMixes) {
    // A flat spectrum is equal-energy grey (the fit of the matching functions: within 0.001).
    const auto flat = spectrum_chromaticity(380, 780, std::vector<double>(41, 7.0));
    ASSERT_TRUE(flat);
    EXPECT_NEAR(flat->x, 1.0 / 3, 1e-3);
    EXPECT_NEAR(flat->y, 1.0 / 3, 1e-3);
    // CIE illuminant A is a black body at 2856 K: (0.4476, 0.4074).
    const auto a = blackbody_chromaticity(2856);
    ASSERT_TRUE(a);
    EXPECT_NEAR(a->x, 0.4476, 2e-3);
    EXPECT_NEAR(a->y, 0.4074, 2e-3);
    // The specification's monitor primaries mixed by its luminances make its white.
    const auto white = mix_chromaticity(
        {{0.265, {0.640, 0.330}}, {0.670, {0.290, 0.600}}, {0.065, {0.150, 0.060}}});
    ASSERT_TRUE(white);
    EXPECT_NEAR(white->x, 1.0 / 3, 0.01);
    EXPECT_NEAR(white->y, 1.0 / 3, 0.01);
    // The same through the reader: cspec, cct and cmix set the current colour.
    const PolygonSoup soup = read(std::string(kSquareVertices) +
                                  "c g =\n cspec 400 700 1 1 1 1\nc w =\n cct 5000\n"
                                  "c\n cmix 1 g 1 w\nm m1 =\n rd 0.3\nf q0 q1 q2\n");
    const Eigen::Vector3d kd = soup.materials[0].material.kd;
    EXPECT_NEAR(kd.sum() / 3, 0.3, 0.03);
    EXPECT_TRUE(contains(read_error("c a =\n cspec 400 700 0 0\n"), "scene.mgf:2: cspec gives no"));
    EXPECT_TRUE(contains(read_error("c\n cmix 1 nope\n"), "undefined name 'nope'"));
}

// Colours of extreme but finite numbers have a chromaticity, computed without overflow: a black
// body at 1e300 K is the Rayleigh-Jeans limit (as at 1e12 K), one at 1e-300 K the band's red end
// (as at 0.5 K), a spectrum or a mix does not see a common factor. Through the reader each is a
// finite reflectance of the luminance asked, and a temperature not above 0 K is refused at its
// own line.
TEST(MgfReader, ExtremeColoursAreComputedOrRefusedAtTheirLine) {
    const auto same = [](const std::optional<Chromaticity>& a,
                         const std::optional<Chromaticity>& b) {
        ASSERT_TRUE(a && b);
        EXPECT_NEAR(a->x, b->x, 1e-9);
        EXPECT_NEAR(a->y, b->y, 1e-9);
    };
    same(blackbody_chromaticity(1e300), blackbody_chromaticity(1e12));
    same(blackbody_chromaticity(1.7e308), blackbody_chromaticity(1e12));
    same(blackbody_chromaticity(1e-300), blackbody_chromaticity(0.5));
    same(blackbody_chromaticity(5e-324), blackbody_chromaticity(0.5));
    const std::vector<double> ramp = {1, 2, 3, 4}, huge = {1e305, 2e305, 3e305, 4e305};
    same(spectrum_chromaticity(380, 780, huge), spectrum_chromaticity(380, 780, ramp));
    same(spectrum_chromaticity(380, 780, std::vector<double>(41, 1e308)),
         spectrum_chromaticity(380, 780, std::vector<double>(41, 1.0)));
    same(mix_chromaticity({{1e308, {0.64, 0.33}}, {1e308, {0.3, 0.6}}}),
         mix_chromaticity({{1, {0.64, 0.33}}, {1, {0.3, 0.6}}}));
    for (const std::string colour :
         {"cct 1e300", "cct 1e-300", "cspec 380 780 1e308 1e308 1e308", "cxy 0.3 1e-320"}) {
        const PolygonSoup soup = read(std::string(kSquareVertices) + "m a =\n c\n  " + colour +
                                      "\n rd 0.5\nf q0 q1 q2\n");
        const Eigen::Vector3d kd = soup.materials[0].material.kd;
        EXPECT_TRUE(kd.allFinite()) << colour << ": " << kd.transpose();
        EXPECT_NEAR(rgb_luminance(kd), 0.5, 1e-6) << colour << ": " << kd.transpose();
    }
    EXPECT_TRUE(contains(read_error("c a =\n cct -5\n"),
                         "scene.mgf:2: cct: a temperature must be above 0 K, got '-5'"));
    EXPECT_TRUE(contains(read_error("c a =\n cct 0\n"), "scene.mgf:2: cct: a temperature"));
}

TEST(MgfReader, TransformationsActInOrderInnerFirst) {
    const std::string text = std::string(kSquareVertices) +
                             "xf -t 1 0 0\n"
                             "xf -s 2 -rz 90\n"  // (x, y) -> 2 (-y, x), then + (1, 0, 0)
                             "f q0 q1 q2 q3\n"
                             "xf\nxf\n";
    const PolygonSoup soup = read(text);
    const auto p = corners(soup, 0);
    EXPECT_TRUE(p[1].isApprox(Eigen::Vector3d(1, 2, 0), 1e-12)) << p[1].transpose();
    EXPECT_TRUE(p[2].isApprox(Eigen::Vector3d(-1, 2, 0), 1e-12)) << p[2].transpose();
    EXPECT_NEAR(area_vector(p).z(), 4, 1e-12);  // still facing +z
    EXPECT_TRUE(contains(read_error("xf -t 1 0 0\n"), "scene.mgf:1: xf is never ended"));
    EXPECT_TRUE(contains(read_error("xf\n"), "scene.mgf:1: xf ends no transformation"));
    EXPECT_TRUE(contains(read_error("xf -q 1\nxf\n"), "scene.mgf:1: unknown transformation"));
    EXPECT_TRUE(contains(read_error("xf -s 0\nxf\n"), "scene.mgf:1: -s 0"));
    EXPECT_TRUE(contains(
        read_error(std::string(kSquareVertices) + "xf -s 1e300 -s 1e300\nf q0 q1 q2\nxf\n"),
        "scene.mgf:10: a coordinate is not finite"));
}

TEST(MgfReader, MirrorsKeepFacesFacingOutward) {
    // A unit cube (prism over the square, extruded against its +z normal) mirrored in x stays
    // a cube of volume +1: its faces still face outwards.
    const std::string cube = std::string(kSquareVertices) + "prism q0 q1 q2 q3 1\n";
    EXPECT_NEAR(signed_volume(read(cube)), 1, 1e-12);
    const PolygonSoup mirrored = read("xf -mx\n" + cube + "xf\n");
    EXPECT_NEAR(signed_volume(mirrored), 1, 1e-12);
    EXPECT_LT(corners(mirrored, 0)[1].x(), 0);
    EXPECT_NEAR(signed_volume(read("xf -s -2\n" + cube + "xf\n")), 8, 1e-12);
}

TEST(MgfReader, ArraysMakeInstances) {
    const std::string text = std::string(kSquareVertices) +
                             "xf -a 3 -t 2 0 0 -a 2 -t 0 3 0 -i 2 -t 0 0 10\n"
                             "f q0 q1 q2 q3\nxf\n";
    const PolygonSoup soup = read(text);
    ASSERT_EQ(soup.polygon_count(), 6u);
    std::set<std::array<double, 3>> origins;
    for (std::size_t k = 0; k < 6; ++k) {
        const Eigen::Vector3d o = corners(soup, k)[0];
        origins.insert({o.x(), o.y(), o.z()});
    }
    const std::set<std::array<double, 3>> expected = {{0, 0, 20}, {2, 0, 20}, {4, 0, 20},
                                                      {0, 3, 20}, {2, 3, 20}, {4, 3, 20}};
    EXPECT_EQ(origins, expected);
    EXPECT_TRUE(contains(read_error("xf -a 0 -t 1 0 0\nxf\n"), "-a needs a positive whole count"));
}

// (An array of polygons is refused sooner, for its polygons: tests/hostile/mgf_limits_test.cpp.)
TEST(MgfReader, ArraysBeyondTheStatementBudgetAreRefused) {
    SceneFiles files;
    MgfOptions options;
    options.max_statements = 1000;
    const auto path = files.write(
        "scene.mgf", std::string(kSquareVertices) + "xf -a 1000000000 -t 1 0 0\nc\nxf\n");
    EXPECT_TRUE(
        contains(scene_error([&] { read_mgf(path, options); }), "more than 1000 statements"));
}

// Found by fuzzing: instances of an empty array ran no statement to count, so 10^9 of them ran
// for minutes. Each instance counts now (all at once, so a refusal is immediate): the `xf` and
// 999 instances are within 1,000 statements, 1,000 instances are not.
TEST(MgfReader, EmptyArraysCountTheirInstances) {
    SceneFiles files;
    MgfOptions options;
    options.max_statements = 1000;
    EXPECT_EQ(read_mgf(files.write("999.mgf", "xf -a 999 -t 1 0 0\nxf\n"), options).polygon_count(),
              0u);
    EXPECT_TRUE(contains(scene_error([&] {
                             read_mgf(files.write("1000.mgf", "xf -a 1000 -t 1 0 0\nxf\n"),
                                      options);
                         }),
                         "1000.mgf:1: more than 1000 statements"));
    const auto path =
        files.write("scene.mgf", std::string(kSquareVertices) + "xf -a 1000000000 -t 1 0 0\nxf\n");
    EXPECT_TRUE(
        contains(scene_error([&] { read_mgf(path, options); }), "scene.mgf:9: more than 1000"));
    files.write("empty.mgf", "# nothing\n");
    const auto top = files.write("top.mgf", "i empty.mgf -a 1000000000 -t 1 0 0\n");
    EXPECT_TRUE(
        contains(scene_error([&] { read_mgf(top, options); }), "top.mgf:1: more than 1000"));
}

TEST(MgfReader, IncludesAreRelativeToTheIncludingFile) {
    SceneFiles files;
    files.write("parts/square.mgf", std::string(kSquareVertices) + "i tri.mgf\nf q0 q1 q2 q3\n");
    files.write("parts/tri.mgf",
                "v t0 =\n p 0 0 1\nv t1 =\n p 1 0 1\nv t2 =\n p 0 1 1\nf t0 t1 t2\n");
    const auto top = files.write("room.mgf", "i parts/square.mgf -t 0 0 5 -a 2 -t 10 0 0\n");
    const PolygonSoup soup = read_mgf(top);
    ASSERT_EQ(soup.polygon_count(), 4u);  // a triangle and a square, twice
    EXPECT_EQ(soup.files.size(), 3u);     // each file read once
    EXPECT_TRUE(corners(soup, 2)[0].isApprox(Eigen::Vector3d(10, 0, 6)));
    EXPECT_TRUE(contains(soup.where(soup.place[0]), "tri.mgf:7"));
    files.write("loop.mgf", "i loop.mgf\n");
    EXPECT_TRUE(contains(scene_error([&] { read_mgf(files.path() / "loop.mgf"); }),
                         "loop.mgf:1: the file includes itself"));
    files.write("missing.mgf", "\n\ni none.mgf\n");
    EXPECT_TRUE(contains(scene_error([&] { read_mgf(files.path() / "missing.mgf"); }),
                         "missing.mgf:3: include:"));
}

// The sphere's area is below the true one by at most (pi / N)^2 of it (mgf_shapes.h), and the
// sphere faces outwards (inwards for a negative radius).
TEST(MgfReader, SphereAreaWithinTheStatedBound) {
    for (int n : {8, 24, 64}) {
        const PolygonSoup soup = read("v c =\n p 1 2 3\nsph c 0.5\n", n);
        EXPECT_EQ(soup.polygon_count(), std::size_t(n * (n / 2)));
        const double exact = 4 * kPi * 0.25;
        const double deficit = 1 - total_area(soup) / exact;
        EXPECT_GT(deficit, 0) << n;
        EXPECT_LT(deficit, (kPi / n) * (kPi / n)) << n;
        EXPECT_GT(signed_volume(soup), 0);
    }
    EXPECT_LT(signed_volume(read("v c =\n p 0 0 0\nsph c -1\n")), 0);
    EXPECT_TRUE(contains(read_error("v c =\nsph c 0\n"), "scene.mgf:2: sph: the radius is 0"));
}

TEST(MgfReader, CylinderAndCone) {
    const int n = 24;
    const double bound = (kPi / n) * (kPi / n);
    const std::string ends = "v a =\n p 0 0 0\nv b =\n p 0 0 2\n";
    const PolygonSoup cyl = read(ends + "cyl a 0.5 b\n", n);
    EXPECT_EQ(cyl.polygon_count(), std::size_t(n));
    EXPECT_NEAR(total_area(cyl), 2 * kPi * 0.5 * 2, bound * 2 * kPi * 0.5 * 2);
    // Outward: the first face's normal points away from the axis.
    const auto p = corners(cyl, 0);
    const Eigen::Vector3d centre = (p[0] + p[1] + p[2] + p[3]) / 4;
    EXPECT_GT(area_vector(p).dot(Eigen::Vector3d(centre.x(), centre.y(), 0)), 0);
    const PolygonSoup cone = read(ends + "cone a 1 b 0\n", n);  // to a point: triangles
    EXPECT_EQ(cone.polygon_count(), std::size_t(n));
    EXPECT_EQ(corners(cone, 0).size(), 3u);
    const double slant = kPi * 1 * std::sqrt(1 + 4);
    EXPECT_NEAR(total_area(cone), slant, bound * slant);
    EXPECT_TRUE(contains(read_error(ends + "cone a 1 b -1\n"), "scene.mgf:5: cone: radii"));
    EXPECT_TRUE(contains(read_error(ends + "cyl a 1 a\n"), "scene.mgf:5: cyl: both ends"));
}

TEST(MgfReader, RingFacesItsNormal) {
    const int n = 24;
    const PolygonSoup ring = read("v c =\n p 0 0 0\n n 0 -1 0\nring c 1 2\n", n);
    EXPECT_EQ(ring.polygon_count(), std::size_t(n));
    const double exact = kPi * (4 - 1);
    EXPECT_NEAR(total_area(ring), exact, (kPi / n) * (kPi / n) * exact);
    for (std::size_t k = 0; k < ring.polygon_count(); ++k)
        EXPECT_LT(area_vector(corners(ring, k)).y(), 0);
    const PolygonSoup disc = read("v c =\n p 0 0 0\n n 0 0 1\nring c 0 1\n", n);
    EXPECT_EQ(corners(disc, 0).size(), 3u);
    EXPECT_TRUE(contains(read_error("v c =\n p 0 0 0\nring c 0 1\n"),
                         "scene.mgf:3: ring: vertex 'c' has no normal"));
    EXPECT_TRUE(
        contains(read_error("v c =\n n 0 0 1\nring c 2 1\n"), "ring: needs 0 <= rmin < rmax"));
}

TEST(MgfReader, TorusEnclosesItsVolume) {
    const int n = 24;
    const PolygonSoup torus = read("v c =\n p 0 0 0\n n 0 0 1\ntorus c 1 3\n", n);
    EXPECT_EQ(torus.polygon_count(), std::size_t(n * n));
    const double major = 2, minor = 1;
    const double area = 4 * kPi * kPi * major * minor,
                 volume = 2 * kPi * kPi * major * minor * minor;
    const double bound = 2 * (kPi / n) * (kPi / n);  // two circles
    EXPECT_NEAR(total_area(torus), area, bound * area);
    EXPECT_NEAR(signed_volume(torus), volume, bound * volume);
    EXPECT_TRUE(
        contains(read_error("v c =\n n 0 0 1\ntorus c 3 1\n"), "torus: needs |rmin| < |rmax|"));
}

TEST(MgfReader, PrismIsAClosedSolid) {
    const PolygonSoup prism = read(std::string(kSquareVertices) + "prism q0 q1 q2 q3 2\n");
    EXPECT_EQ(prism.polygon_count(), 6u);
    EXPECT_NEAR(total_area(prism), 2 + 4 * 2, 1e-12);
    EXPECT_NEAR(signed_volume(prism), 2, 1e-12);
    EXPECT_NEAR(corners(prism, 1)[0].z(), -2, 1e-12);  // extruded against the +z normal
    EXPECT_NEAR(signed_volume(read(std::string(kSquareVertices) + "prism q0 q1 q2 q3 -2\n")), -2,
                1e-12);
    EXPECT_TRUE(contains(read_error(std::string(kSquareVertices) + "prism q0 q1 q2 q3 0\n"),
                         "scene.mgf:9: prism: the length is 0"));
}

TEST(MgfReader, FacesWithExplicitHolesAreRefused) {
    EXPECT_TRUE(contains(read_error(std::string(kSquareVertices) + "fh q0 q1 q2 q3\n"),
                         "scene.mgf:9: fh (a face with holes) is not read"));
}

}  // namespace
}  // namespace hmcr

namespace hmcr {
namespace {

double mesh_area(PatchMesh& mesh, Eigen::Vector3d& emitted_power) {
    const FaceMaterials material(mesh);
    double area = 0;
    emitted_power.setZero();
    for (auto fh : mesh.faces()) {
        std::vector<Eigen::Vector3d> p;
        for (auto vh : mesh.fv_range(fh)) {
            p.emplace_back(mesh.point(vh)[0], mesh.point(vh)[1], mesh.point(vh)[2]);
        }
        const double a = area_vector(p).norm();
        area += a;
        const auto& e = material[fh].emission;
        emitted_power += a * Eigen::Vector3d(e[0], e[1], e[2]);
    }
    return area;
}

// The bundled MGF room (scenes/mgf-room): two tables from one included file, each with legs
// from a 2 x 2 array, and two lights from an array. Everything is counted by hand.
TEST(MgfScene, ArraysAndIncludesGiveTheExpectedPatchesAreaAndPower) {
    Scene scene = load_scene("mgf-room");
    const int n = kDefaultCurveSegments;
    // Room 6 faces, lights 2, per table a prism top (6) and 4 legs of n quads.
    EXPECT_EQ(scene.mesh.n_faces(), 6u + 2 + 2 * (6 + 4 * std::size_t(n)));
    EXPECT_TRUE(scene.repairs.empty());
    const double room = 2 * 4 * 3 + 2 * 4 * 2.5 + 2 * 3 * 2.5;
    const double lights = 2 * 0.5 * 1;
    const double top = 2 * 1.2 * 0.8 + 2 * (1.2 + 0.8) * 0.04;
    const double leg = n * 2 * 0.03 * std::sin(kPi / n) * 0.72;  // n flat quads
    Eigen::Vector3d power;
    EXPECT_NEAR(mesh_area(scene.mesh, power), room + lights + 2 * (top + 4 * leg), 1e-9);
    // ed 50 lm/m^2 of neutral colour over 1 m^2: E = 50 in every channel.
    EXPECT_TRUE(power.isApprox(Eigen::Vector3d::Constant(50), 1e-12)) << power.transpose();
    // The second table is turned a quarter: its top spans x in [2.8, 3.6], y in [1.2, 2.4].
    double max_x = 0;
    for (auto vh : scene.mesh.vertices()) max_x = std::max(max_x, scene.mesh.point(vh)[0]);
    EXPECT_NEAR(max_x, 4, 1e-12);  // the room's wall, not a misplaced table
    EXPECT_EQ(scene.views.front().name, "door");
}

// A scene file can name an .mgf mesh and set the tessellation; the command line's wins.
TEST(MgfScene, SceneFileSetsTheSegments) {
    SceneFiles files;
    files.write("ball.mgf", "m lamp =\n ed 10\nv c =\n p 0 0 0\nsph c 1\n");
    const auto json = files.write("ball.json", R"({"mesh": "ball.mgf", "mgf_segments": 8})");
    EXPECT_EQ(load_scene(json.string()).mesh.n_faces(), 8u * 4);
    LoadOptions options;
    options.curve_segments = 12;
    const Scene scene = load_scene(json.string(), options);
    EXPECT_EQ(scene.mesh.n_faces(), 12u * 6);
    EXPECT_EQ(scene.curve_segments, 12);
    const auto bad = files.write("bad.json", R"({"mesh": "ball.mgf", "mgf_segments": 2})");
    EXPECT_TRUE(contains(scene_error([&] { load_scene(bad.string()); }), "mgf_segments: must be"));
}

}  // namespace
}  // namespace hmcr
