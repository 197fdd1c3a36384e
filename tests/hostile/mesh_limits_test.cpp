// SPDX-License-Identifier: Apache-2.0
// Hostile meshes at the OBJ reader's limits (docs/usage.md#bad-input): faces of hundreds and
// thousands of corners read whole and alike in OBJ and MGF, material names with spaces, a line
// too long, and warnings by the hundred thousand.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

// The run summary's scene part after `hmcr solve FILE -o out.vtp`.
nlohmann::json solved_scene(const std::filesystem::path& dir, const std::string& file) {
    // One-sided: the area is the polygons' (a two-sided face counts twice, docs/design.md §1.3).
    const CliRun r = run_hmcr("solve " + file + " --sides 1 --rays 1000 -q -o out.vtp", dir);
    EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.err;
    return nlohmann::json::parse(read_file(dir / "out.json"))["scene"];
}

// The corners of a star of n (even) corners in z = 0, radii 1 and 0.4 alternating,
// counter-clockwise: a simple polygon, concave at every other corner, of area
// 0.2 n sin(2 pi / n).
std::vector<std::array<double, 2>> star(int n) {
    std::vector<std::array<double, 2>> corners;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n, r = k % 2 ? 0.4 : 1.0;
        corners.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return corners;
}

double star_area(int n) { return 0.2 * n * std::sin(2 * std::numbers::pi / n); }

// The star under a 2 x 2 emitter at z = 1, as OBJ (with its MTL) and as MGF.
void write_star(const TempDir& temp, int n) {
    std::string obj = "mtllib star.mtl\n", mgf = "m grey =\nc\nrd 0.5\nm light =\nc\ned 3\nrd 0\n";
    std::string obj_face = "usemtl grey\nf", mgf_face = "m grey\nf";
    int k = 0;
    for (const auto& [x, y] : star(n)) {
        obj += fmt::format("v {:.17g} {:.17g} 0\n", x, y);
        mgf += fmt::format("v p{} =\np {:.17g} {:.17g} 0\n", k, x, y);
        obj_face += fmt::format(" {}", ++k);
        mgf_face += fmt::format(" p{}", k - 1);
    }
    obj += "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n" + obj_face +
           fmt::format("\nusemtl light\nf {} {} {} {}\n", n + 1, n + 4, n + 3, n + 2);
    mgf += "v l0 =\np -1 -1 1\nv l1 =\np 1 -1 1\nv l2 =\np 1 1 1\nv l3 =\np -1 1 1\n" + mgf_face +
           "\nm light\nf l0 l3 l2 l1\n";
    temp.write("star.obj", obj);
    temp.write("star.mtl", "newmtl grey\nKd 0.5 0.5 0.5\nnewmtl light\nKd 0 0 0\nKe 1 1 1\n");
    temp.write("star.mgf", mgf);
}

// A face of 260 corners once wrapped its corner count modulo 256 and shifted every later face:
// 3 patches and 1 m^2, silently.
TEST_F(Hostile, AFaceOfMoreThan255CornersIsReadWhole) {
    const std::filesystem::path data = std::filesystem::path(HMCR_TEST_DATA) / "plates-260";
    for (const char* file : {"plates-260.obj", "plates-260.mtl"}) {
        std::filesystem::copy_file(data / file, dir() / file);
    }
    const nlohmann::json scene = solved_scene(dir(), "plates-260.obj");
    EXPECT_EQ(scene["patches"], 2 + 258);  // the 260-gon in 258 triangles
    const double area = 2 + 130 * std::sin(2 * std::numbers::pi / 260);
    EXPECT_NEAR(scene["total_area_m2"].get<double>(), area, 1e-12 * area);
}

// Simple stars of hundreds to thousands of corners: OBJ once refused them as self-intersecting
// (the wrapped corner count again) where MGF read them. Both read them, the same.
TEST_F(Hostile, StarPolygonsAreReadAlikeInObjAndMgf) {
    for (int n : {300, 2000}) {
        write_star(m_temp, n);
        const nlohmann::json obj = solved_scene(dir(), "star.obj");
        const nlohmann::json mgf = solved_scene(dir(), "star.mgf");
        EXPECT_EQ(obj["patches"], n - 2 + 1) << n;
        EXPECT_EQ(mgf["patches"], obj["patches"]) << n;
        const double area = star_area(n) + 4;
        EXPECT_NEAR(obj["total_area_m2"].get<double>(), area, 1e-12 * area) << n;
        EXPECT_NEAR(mgf["total_area_m2"].get<double>(), area, 1e-12 * area) << n;
    }
}

// Beyond the documented 10,000 corners both readers refuse the face, at its line, alike.
TEST_F(Hostile, AFaceOfTooManyCornersIsRefusedAlikeInObjAndMgf) {
    write_star(m_temp, 10'002);
    refused("solve star.obj -o out.vtp",
            "star.obj:10009: polygon with 10002 corners: at most 10000 are triangulated");
    refused("solve star.mgf -q -o out.vtp",
            "star.mgf:20021: polygon with 10002 corners: at most 10000 are triangulated");
}

// `newmtl` and `usemtl` name a material by the rest of their line, trimmed, as Blender's
// importer reads them: a name with spaces is one name.
TEST_F(Hostile, AMaterialNameWithSpacesIsOneName) {
    plates(with(kPlatesObj, "usemtl receiver", "usemtl  grey receiver  "),
           with(kPlatesMtl, "newmtl receiver", "newmtl grey receiver\t"));
    const nlohmann::json scene = solved_scene(dir(), "plates.obj");
    EXPECT_EQ(scene["patches"], 2);
    // Another name is still another material.
    plates(with(kPlatesObj, "usemtl receiver", "usemtl grey"),
           with(kPlatesMtl, "newmtl receiver", "newmtl grey receiver"));
    refused("solve plates.obj -o out.vtp", "'grey', which no");
}

// A line of 5 MB: refused at its line before it costs memory (a 200 MB line took 2.3 GB).
TEST_F(Hostile, ALineTooLongIsRefusedWithItsLine) {
    std::string face = "f";
    while (face.size() < 5'000'000) face += " 1";
    plates(std::string(kPlatesObj) + face + "\n");
    refused("solve plates.obj -o out.vtp",
            "plates.obj:14: a line of 5000001 bytes: hmcr reads lines of at most 4194304");
    plates(kPlatesObj, std::string(kPlatesMtl) + "newmtl " + std::string(5'000'000, 'x') + "\n");
    refused("info plates.obj", "plates.mtl:7: a line of 5000007 bytes");
}

// The stderr lines of a run that start with `prefix`.
std::size_t lines_starting(const std::string& text, const std::string& prefix) {
    std::size_t n = 0;
    for (std::size_t at = 0; at < text.size(); at = text.find('\n', at) + 1) {
        n += text.compare(at, prefix.size(), prefix) == 0;
        if (text.find('\n', at) == std::string::npos) break;
    }
    return n;
}

// 100,000 unknown MTL statements: grouped by statement with their count, and a few lines in
// all, whether the load then succeeds or fails (one line of error, the last).
TEST_F(Hostile, WarningsAreGroupedAndBounded) {
    std::string many;
    for (int k = 0; k < 50'000; ++k) many += fmt::format("KE 1 1 1\nunknown{} 2\n", k);
    plates(kPlatesObj, kPlatesMtl + many);
    CliRun r = accepted("solve plates.obj --rays 1000 -o out.vtp");
    EXPECT_LE(lines_starting(r.err, "hmcr: warning:"), 21u) << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), 8000u);
    EXPECT_NE(r.err.find("plates.mtl:7: unknown MTL statement 'KE' ignored (50000 times"),
              std::string::npos)
        << r.err.substr(0, 2000);
    plates(kPlatesObj, with(kPlatesMtl, "Ke 0.3 0.3 0.3", "Ke 0 0 0") + many);
    r = run_hmcr("solve plates.obj -o out.vtp", dir());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_LE(lines_starting(r.err, "hmcr: warning:"), 21u) << r.err.substr(0, 2000);
    EXPECT_EQ(lines_starting(r.err, "hmcr: error:"), 1u);
    EXPECT_NE(r.err.rfind("\nhmcr: error: plates.obj: no face emits light"), std::string::npos)
        << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), 8000u);
}

}  // namespace
}  // namespace hmcr::test
