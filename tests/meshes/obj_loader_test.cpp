// SPDX-License-Identifier: Apache-2.0
// load_obj: a good file gives the right patches, materials and adjacency; every validation
// error of docs/design.md §1 throws a InputError naming the right `file:line`.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>

#include "meshes/obj_lines.h"
#include "meshes/obj_reader.h"
#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

constexpr const char* kMtl =
    "newmtl white\n"    // 1
    "Kd 0.5 0.5 0.5\n"  // 2
    "newmtl light\n"    // 3
    "Kd 0.5 0.5 0.5\n"  // 4
    "Ke 1 2 3\n";       // 5

// Lines 1-2 of every test OBJ; its statements start on line 3.
constexpr const char* kHeader =
    "mtllib scene.mtl\n"
    "usemtl white\n";

// The InputError message of loading kHeader + body with the given MTL.
std::string obj_error(const std::string& body, const std::string& mtl = kMtl, bool strict = false) {
    SceneFiles files;
    files.write("scene.mtl", mtl);
    const auto obj = files.write("scene.obj", kHeader + body);
    LoadOptions options;
    options.strict = strict;
    return scene_error([&] { load_obj(obj, options); });
}

// The same with --strict: what the repairs would fix (repairs_test.cpp) is refused as it was.
std::string strict_error(const std::string& body, const std::string& mtl = kMtl) {
    return obj_error(body, mtl, true);
}

// Two unit quads side by side in z = 0 (normal +z), sharing the edge x = 1; the second one
// is the light and repeats the position (1, 0, 0) in its own `v` statement (line 9).
constexpr const char* kTwoQuads =
    "v 0 0 0\n"  // 3
    "v 1 0 0\n"  // 4
    "v 1 1 0\n"  // 5
    "v 0 1 0\n"  // 6
    "v 2 0 0\n"  // 7
    "v 2 1 0\n"  // 8
    "v 1 0 0\n"  // 9
    "# the grey quad\n"
    "f 1 2 3 4\n"  // 11
    "usemtl light\n"
    "f 7 5 6 -5\n";  // 13: (1,0,0) (2,0,0) (2,1,0) (1,1,0)

TEST(ObjLoader, LoadsFacesMaterialsAndLines) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    PatchMesh mesh = load_obj(files.write("scene.obj", std::string(kHeader) + kTwoQuads));
    ASSERT_EQ(mesh.n_faces(), 2u);
    const FaceMaterials material(mesh);
    auto line = source_line_prop(mesh);
    const OpenMesh::FaceHandle grey(0), light(1);
    EXPECT_EQ(material[grey].reflectance, OpenMesh::Vec3d(0.5, 0.5, 0.5));
    EXPECT_EQ(material[grey].emission, OpenMesh::Vec3d(0, 0, 0));
    EXPECT_EQ(material[light].emission, OpenMesh::Vec3d(1, 2, 3) * std::numbers::pi);
    EXPECT_EQ(line[grey], 11);
    EXPECT_EQ(line[light], 13);
}

TEST(ObjLoader, WeldsEqualPositionsSoNeighboursShareAnEdge) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    PatchMesh mesh = load_obj(files.write("scene.obj", std::string(kHeader) + kTwoQuads));
    EXPECT_EQ(mesh.n_vertices(), 6u);
    int interior_edges = 0;
    for (auto eh : mesh.edges()) interior_edges += mesh.is_boundary(eh) ? 0 : 1;
    EXPECT_EQ(interior_edges, 1);
    for (auto eh : mesh.edges()) {
        if (mesh.is_boundary(eh)) continue;
        const auto he = mesh.halfedge_handle(eh, 0);
        EXPECT_EQ(mesh.point(mesh.from_vertex_handle(he))[0], 1.0);
        EXPECT_EQ(mesh.point(mesh.to_vertex_handle(he))[0], 1.0);
    }
}

TEST(ObjLoader, KeepsFacesOpenMeshRefuses) {
    // Three triangles on the edge (0,0,0)-(1,0,0): OpenMesh refuses the third one (complex
    // edge); it must be kept with its own vertices.
    const std::string body =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 1\n"
        "usemtl light\n"
        "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    PatchMesh mesh = load_obj(files.write("scene.obj", kHeader + body));
    EXPECT_EQ(mesh.n_faces(), 3u);
    EXPECT_EQ(source_line_prop(mesh)[OpenMesh::FaceHandle(2)], 11);
}

TEST(ObjLoader, DefaultMaterialForFacesWithout) {
    SceneFiles files;
    const auto obj = files.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    LoadOptions options;
    options.default_material = Material{"default", {0.25, 0.5, 0.75}, {2, 2, 2}};
    PatchMesh mesh = load_obj(obj, options);
    ASSERT_EQ(mesh.n_faces(), 1u);
    const FaceMaterial& m = FaceMaterials(mesh)[OpenMesh::FaceHandle(0)];
    EXPECT_EQ(m.reflectance, OpenMesh::Vec3d(0.25, 0.5, 0.75));
    EXPECT_EQ(m.emission, OpenMesh::Vec3d(2, 2, 2) * std::numbers::pi);
}

TEST(ObjLoader, UnreadableFile) {
    SceneFiles files;
    const auto missing = files.path() / "missing.obj";
    EXPECT_EQ(scene_error([&] { load_obj(missing); }), missing.string() + ": no such file");
    EXPECT_TRUE(contains(scene_error([&] { load_obj(files.path()); }), ": is a directory"));
}

TEST(ObjLoader, UnreadableMaterialLibrary) {
    SceneFiles files;
    const auto obj = files.write("scene.obj", "v 0 0 0\nmtllib nowhere.mtl\n");
    EXPECT_TRUE(contains(scene_error([&] { load_obj(obj); }),
                         "scene.obj:2: cannot read material library 'nowhere.mtl'"));
}

TEST(ObjLoader, ParseErrorInNumber) {
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 zero\n"), "scene.obj:4: cannot parse number"));
    EXPECT_TRUE(contains(obj_error("v 0 0\n"), "scene.obj:3: 'v' needs 3 to 7 numbers"));
}

TEST(ObjLoader, ParseErrorUnknownStatement) {
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nvertex 1 2 3\n"),
                         "scene.obj:4: unknown OBJ statement 'vertex'"));
}

TEST(ObjLoader, ParseErrorBadVertexReference) {
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n"),
                         "scene.obj:6: bad vertex reference '0'"));
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
                         "scene.obj:6: vertex reference '4' is out of range (3 vertices)"));
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/x\n"),
                         "scene.obj:6: bad vertex reference '3/x'"));
}

TEST(ObjLoader, ParseErrorLineNumbersCountCarriageReturns) {
    EXPECT_TRUE(contains(obj_error("v 0 0 0\r\nv 0 0 0\rv 1 1 q\n"), "scene.obj:5:"));
}

TEST(ObjLoader, PolygonWithMoreThanFourVertices) {
    const std::string pentagon = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n";
    EXPECT_TRUE(contains(strict_error(pentagon),
                         "scene.obj:8: polygon with 5 vertices: --strict reads triangles and "
                         "convex quads only"));
}

TEST(ObjLoader, PolygonWithFewerThanThreeVertices) {
    EXPECT_TRUE(
        contains(obj_error("v 0 0 0\nv 1 0 0\nf 1 2\n"), "scene.obj:5: polygon with 2 vertices"));
}

TEST(ObjLoader, NanOrInfCoordinate) {
    EXPECT_TRUE(
        contains(obj_error("v 0 0 0\nv 1 nan 0\n"), "scene.obj:4: 'nan' is not a finite number"));
    EXPECT_TRUE(contains(obj_error("v -inf 0 0\n"), "scene.obj:3: '-inf' is not a finite"));
    EXPECT_TRUE(contains(obj_error("v 1e999 0 0\n"), "scene.obj:3: number '1e999' is out of"));
}

TEST(ObjLoader, ZeroAreaTriangle) {
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
                         "scene.obj:6: degenerate face"));
}

TEST(ObjLoader, TinyAreaRelativeToSize) {
    // Area 5e-13 m^2 against a largest edge of 1 m: below 1e-12 x 1^2.
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 0.5 1e-12 0\nf 1 2 3\n"),
                         "scene.obj:6: degenerate face"));
}

TEST(ObjLoader, RepeatedVertex) {
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"),
                         "scene.obj:6: degenerate face: corners 2 and 3 are the same point"));
    // Two `v` statements at the same position are one vertex after welding.
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 3 4\n"),
                         "scene.obj:7: degenerate face: corners 2 and 4 are the same point"));
}

TEST(ObjLoader, NonPlanarQuad) {
    // The 4th vertex is 1 mm above the plane z = 0; the tolerance is 1e-4 x 1.414 m.
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.001\nf 1 2 3 4\n"),
                         "scene.obj:7: non-planar quad: the 4th vertex is 1 mm off the plane "
                         "of the other three (tolerance 0.141 mm"));
}

TEST(ObjLoader, NearlyPlanarQuadLoads) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    const auto obj = files.write("scene.obj", std::string(kHeader) +
                                                  "usemtl light\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                                  "v 0 1 0.0001\nf 1 2 3 4\n");
    EXPECT_EQ(load_obj(obj).n_faces(), 1u);
}

TEST(ObjLoader, NonConvexQuad) {
    // A dart: the corner at (0.3, 0.3) turns clockwise, the others counter-clockwise.
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 0.3 0.3 0\nv 0 1 0\nf 1 2 3 4\n"),
                         "scene.obj:7: non-convex quad: corner 3 turns the other way"));
    // A bow-tie, whose vector area is zero.
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n"),
                         "scene.obj:7: non-convex quad"));
}

TEST(ObjLoader, DuplicateFaces) {
    // A face, the same face seen from the back (its back side, meshes/coincident_faces.h) and a
    // third face on the same vertices: a surface has two sides.
    const std::string body =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f 1 2 3 4\n"                 // 7
        "f 4 3 2 1\n"                 // 8
        "usemtl light\nf 2 3 4 1\n";  // 10
    EXPECT_TRUE(contains(obj_error(body),
                         "scene.obj:10: a third face on the same vertices as "
                         "the faces on lines 7 and 8: a surface has two sides"));
    // Strict: a copy is refused, with both lines.
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 2 3 1\n"),
                         "scene.obj:7: duplicate face: same vertices as the face on line 6"));
}

TEST(ObjLoader, FaceWithoutMaterial) {
    SceneFiles files;
    const auto obj = files.write("scene.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_TRUE(contains(scene_error([&] { load_obj(obj); }), "scene.obj:4: face has no material"));
    EXPECT_TRUE(
        contains(obj_error("usemtl purple\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                 "scene.obj:7: face uses material 'purple', which no loaded material file"));
}

TEST(ObjLoader, ReflectanceNotBelowOne) {
    const std::string mtl = "# grey\nnewmtl white\nKd 0.5 1.2 0.5\nKe 1 1 1\n";
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mtl),
                         "scene.mtl:3: reflectance 1.2 of material 'white' is above 1"));
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mtl),
                         "scene.mtl:3: reflectance 1.2 of material 'white' is not below 1"));
    // 1 itself is a repair (accepted with a warning), refused only by --strict.
    const std::string white = "newmtl white\nKe 1 1 1\nKd 1 1 1\n";
    EXPECT_TRUE(contains(strict_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", white),
                         "scene.mtl:3: reflectance 1 of material 'white' is not below 1"));
}

TEST(ObjLoader, NegativeReflectance) {
    const std::string mtl = "newmtl white\nKd 0.5 0.5 -0.1\n";
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mtl),
                         "scene.mtl:2: reflectance -0.1 of material 'white' is negative"));
}

TEST(ObjLoader, NegativeEmission) {
    const std::string mtl = "newmtl white\nKd 0.5 0.5 0.5\n\nKe 1 -2 1\n";
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mtl),
                         "scene.mtl:4: emission -2 of material 'white' is negative"));
}

TEST(ObjLoader, MaterialParseError) {
    const std::string mtl = "newmtl white\nKd 0.5 0.5\n";
    EXPECT_TRUE(
        contains(obj_error("v 0 0 0\n", mtl), "scene.mtl:2: 'Kd' needs three numbers (r g b)"));
}

TEST(ObjLoader, NoEmitter) {
    const std::string path_end = "scene.obj: no face emits light";
    EXPECT_TRUE(contains(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), path_end));
}

// Measuring a scene's geometry (`hmcr info`) needs no light and no materials; the other checks
// still apply.
TEST(ObjLoader, GeometryNeedsNoEmitterAndNoMaterial) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    LoadOptions options;
    options.use = SceneUse::geometry;
    const std::string head = std::string(kHeader) + "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const PatchMesh mesh = load_obj(files.write("scene.obj", head + "f 1 2 3\n"), options);
    EXPECT_EQ(mesh.n_faces(), 1u);
    const auto bare = files.write("bare.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(load_obj(bare, options).n_faces(), 1u);
    const auto bad = files.write("bad.obj", head + "v 0 nan 0\nf 1 2 4\n");
    EXPECT_TRUE(contains(scene_error([&] { load_obj(bad, options); }), "bad.obj:"));
}

TEST(ObjLoader, NoFaces) { EXPECT_TRUE(contains(obj_error("v 0 0 0\n"), "scene.obj: no faces")); }

// The soup of kHeader + body (with kMtl or the given MTL).
PolygonSoup soup_of(const std::string& body, const std::string& mtl = kMtl) {
    SceneFiles files;
    files.write("scene.mtl", mtl);
    return read_obj(files.write("scene.obj", kHeader + body));
}

// A face's corners are read whatever their count: 300 of them, and the faces after it keep
// theirs (a count kept in a byte once wrapped at 256 and shifted every later face).
TEST(ObjLoader, AFaceOfMoreThan255CornersIsReadWhole) {
    std::string body, face = "f";
    for (int k = 0; k < 300; ++k) {
        body += fmt::format("v {} {} 0\n", k, k * k);
        face += fmt::format(" {}", k + 1);
    }
    const PolygonSoup soup = soup_of(body + face + "\nf 3 2 1\n");
    ASSERT_EQ(soup.polygon_count(), 2u);
    ASSERT_EQ(soup.corners(0).size(), 300u);
    for (std::uint32_t k = 0; k < 300; ++k) EXPECT_EQ(soup.corners(0)[k], k);
    EXPECT_EQ(std::vector<std::uint32_t>(soup.corners(1).begin(), soup.corners(1).end()),
              (std::vector<std::uint32_t>{2, 1, 0}));
    EXPECT_EQ(soup.where(soup.place[1]), soup.files[0].string() + ":304");
}

// Numbers are read as the nearest double: "0.75" is 0.75 and "0.3" is 0.3 (a reader that
// summed digit times 0.1 made them 0.7500000000000001 and 0.30000000000000004).
TEST(ObjLoader, NumbersAreReadExactly) {
    const PolygonSoup soup = soup_of("v 0.75 0.3 -1.75e-1\nv 0.5528 1e3 0\nv 0 1 0\nf 1 2 3\n",
                                     "newmtl white\nKd 0.3 0.725 0.7\nKe 0.3183098861837907 0 0\n");
    EXPECT_EQ(soup.positions[0], Eigen::Vector3d(0.75, 0.3, -0.175));
    EXPECT_EQ(soup.positions[1], Eigen::Vector3d(0.5528, 1000, 0));
    ASSERT_EQ(soup.materials.size(), 1u);
    EXPECT_EQ(soup.materials[0].material.kd, Eigen::Vector3d(0.3, 0.725, 0.7));
    EXPECT_EQ(soup.materials[0].material.ke, Eigen::Vector3d(0.3183098861837907, 0, 0));
}

// `newmtl` and `usemtl` take the rest of the line, trimmed, as the name (Blender's rule).
TEST(ObjLoader, MaterialNamesMayHoldSpaces) {
    const PolygonSoup soup =
        soup_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \tdark  grey \nf 1 2 3\n",
                "newmtl dark  grey\t\nKd 0.2 0.2 0.2 # comment\nnewmtl dark\nKd 0.1 0.1 0.1\n");
    ASSERT_EQ(soup.materials.size(), 2u);
    EXPECT_EQ(soup.materials[0].material.name, "dark  grey");
    EXPECT_EQ(soup.materials[1].material.name, "dark");
    EXPECT_EQ(soup.material[0], 0);
    EXPECT_TRUE(contains(obj_error("v 0 0 0\n", "newmtl # no name\n"),
                         "scene.mtl:1: newmtl needs a material name"));
}

// A line longer than kMaxObjLineBytes is refused at its line, in an OBJ and in an MTL.
TEST(ObjLoader, ALineTooLongIsRefused) {
    const std::string face = "f" + std::string(kMaxObjLineBytes, ' ') + "1 2 3\n";
    EXPECT_TRUE(contains(obj_error("v 0 0 0\n" + face), "scene.obj:4: a line of " +
                                                            std::to_string(face.size() - 1) +
                                                            " bytes: hmcr reads lines of at most " +
                                                            std::to_string(kMaxObjLineBytes)));
    EXPECT_TRUE(contains(obj_error("v 0 0 0\n", "Ka" + std::string(kMaxObjLineBytes, ' ')),
                         "scene.mtl:1: a line of"));
}

// 10,000 unknown statements of two kinds: two warnings, each with its count.
TEST(ObjLoader, UnknownMtlStatementsAreGroupedByName) {
    std::string mtl = "newmtl white\nKd 0.5 0.5 0.5\n";
    for (int k = 0; k < 5000; ++k) mtl += "KE 1 1 1\nillumination 2\n";
    const PolygonSoup soup = soup_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", mtl);
    ASSERT_EQ(soup.warnings.size(), 2u);
    EXPECT_TRUE(
        contains(soup.warnings[0], "scene.mtl:3: unknown MTL statement 'KE' ignored (5000 times"));
    EXPECT_TRUE(contains(soup.warnings[1],
                         "scene.mtl:4: unknown MTL statement 'illumination' ignored (5000 times"));
}

}  // namespace
}  // namespace hmcr
