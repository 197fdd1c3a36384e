// SPDX-License-Identifier: Apache-2.0
// read_ply through load_mesh: ascii and binary files give the same patches and materials (face
// colours, vertex colours averaged, emission properties); bad and hostile files are refused with
// one line naming the file and the line (or the face of a binary file).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <numbers>

#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

// Two unit quads side by side in z = 0, the second one a light: uchar colours and float
// emission per face. With the two lines kPlyQuads adds, the header is lines 1-16, the vertices
// lines 17-22 and the faces 23-24.
constexpr const char* kPlyQuadsHeader =
    "ply\n"
    "format ascii 1.0\n"
    "comment two quads\n"
    "element vertex 6\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "property float emission_red\n";

std::string ply_quads(const std::string& header_end, const std::string& face_end) {
    return std::string(kPlyQuadsHeader) + header_end +
           "0 0 0\n"
           "1 0 0\n"
           "1 1 0\n"
           "0 1 0\n"
           "2 0 0\n"
           "2 1 0\n"
           "4 0 1 2 3 51 102 153 0 0 0\n" +
           "4 1 4 5 2 204 0 0 1 2 3" + face_end + "\n";
}

const std::string kPlyQuads =
    ply_quads("property float emission_green\nproperty float emission_blue\nend_header\n", "");

// The message of loading `text` as scene.ply, its folder left out.
std::string ply_error(const std::string& text, bool strict = false) {
    SceneFiles files;
    const auto ply = files.write("scene.ply", text);
    LoadOptions options;
    options.strict = strict;
    std::string message = scene_error([&] { load_mesh(ply, options); });
    const std::string folder = files.path().string() + "/";
    if (message.rfind(folder, 0) == 0) message.erase(0, folder.size());
    return message;
}

TEST(PlyReader, FaceColoursAreReflectanceAndEmissionPropertiesRadiance) {
    SceneFiles files;
    MeshFile file = load_mesh(files.write("scene.ply", kPlyQuads));
    PatchMesh& mesh = file.mesh;
    ASSERT_EQ(mesh.n_faces(), 2u);
    EXPECT_EQ(mesh.n_vertices(), 6u);
    const FaceMaterials material(mesh);
    const OpenMesh::FaceHandle grey(0), light(1);
    EXPECT_EQ(material[grey].reflectance, OpenMesh::Vec3d(51 / 255.0, 102 / 255.0, 153 / 255.0));
    EXPECT_EQ(material[grey].emission, OpenMesh::Vec3d(0, 0, 0));
    EXPECT_EQ(material[light].reflectance, OpenMesh::Vec3d(204 / 255.0, 0, 0));
    EXPECT_EQ(material[light].emission, OpenMesh::Vec3d(1, 2, 3) * std::numbers::pi);
    EXPECT_EQ(source_line_prop(mesh)[grey], 23);
    EXPECT_EQ(source_line_prop(mesh)[light], 24);
    EXPECT_TRUE(file.repairs.empty());
}

TEST(PlyReader, FacesOfEqualColoursShareOneMaterial) {
    SceneFiles files;
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
        "property double z\nelement face 2\nproperty list uchar uint vertex_index\n"
        "property float red\nproperty float green\nproperty float blue\n"
        "property double emission_red\nproperty double emission_green\n"
        "property double emission_blue\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
        "3 0 1 2 0.25 0.5 0.75 1 1 1\n"
        "3 0 2 3 0.25 0.5 0.75 1 1 1\n";
    PatchMesh mesh = load_mesh(files.write("scene.ply", text)).mesh;
    const FaceMaterials material(mesh);
    EXPECT_EQ(material.table().size(), 1u);
    EXPECT_EQ(material[OpenMesh::FaceHandle(1)].reflectance, OpenMesh::Vec3d(0.25, 0.5, 0.75));
}

TEST(PlyReader, VertexColoursAreAveragedOverTheFace) {
    SceneFiles files;
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty float red\nproperty float green\nproperty float blue\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0.1 0.2 0.3\n"
        "1 0 0 0.4 0.5 0.6\n"
        "0 1 0 0.7 0.8 0.9\n"
        "3 0 1 2\n";
    LoadOptions geometry;
    geometry.use = SceneUse::geometry;  // no emitter needed
    PatchMesh mesh = load_mesh(files.write("scene.ply", text), geometry).mesh;
    const FaceMaterial& m = FaceMaterials(mesh)[OpenMesh::FaceHandle(0)];
    EXPECT_EQ(m.reflectance,
              OpenMesh::Vec3d((0.1 + 0.4 + 0.7) / 3, (0.2 + 0.5 + 0.8) / 3, (0.3 + 0.6 + 0.9) / 3));
    EXPECT_EQ(m.emission, OpenMesh::Vec3d(0, 0, 0));  // no emission properties: 0
}

// The binary encoding of kPlyQuads' data in the given byte order.
std::string binary_ply_quads(bool big_endian) {
    std::string bytes;
    const auto put = [&](const void* p, std::size_t n) {
        std::string raw(static_cast<const char*>(p), n);
        if (big_endian != (std::endian::native == std::endian::big)) {
            std::reverse(raw.begin(), raw.end());
        }
        bytes += raw;
    };
    const float xyz[6][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    for (const auto& v : xyz) {
        for (const float c : v) put(&c, 4);
    }
    const std::int32_t corners[2][4] = {{0, 1, 2, 3}, {1, 4, 5, 2}};
    const unsigned char rgb[2][3] = {{51, 102, 153}, {204, 0, 0}};
    const float emission[2][3] = {{0, 0, 0}, {1, 2, 3}};
    for (int f = 0; f < 2; ++f) {
        bytes += char(4);
        for (const std::int32_t c : corners[f]) put(&c, 4);
        for (const unsigned char c : rgb[f]) bytes += char(c);
        for (const float e : emission[f]) put(&e, 4);
    }
    return std::string(kPlyQuadsHeader) + "property float emission_green\n" +
           "property float emission_blue\nend_header\n" + bytes;
}

TEST(PlyReader, BinaryFilesOfBothByteOrdersReadAsTheAsciiOne) {
    for (const char* order : {"binary_little_endian", "binary_big_endian"}) {
        SceneFiles files;
        std::string text = binary_ply_quads(std::string(order) == "binary_big_endian");
        text.replace(text.find("ascii"), 5, order);
        PatchMesh binary = load_mesh(files.write("binary.ply", text)).mesh;
        PatchMesh ascii = load_mesh(files.write("ascii.ply", kPlyQuads)).mesh;
        EXPECT_EQ(geometry_hash(binary), geometry_hash(ascii)) << order;
        const FaceMaterials a(ascii), b(binary);
        for (int f = 0; f < 2; ++f) {
            EXPECT_EQ(b[OpenMesh::FaceHandle(f)].reflectance,
                      a[OpenMesh::FaceHandle(f)].reflectance);
            EXPECT_EQ(b[OpenMesh::FaceHandle(f)].emission, a[OpenMesh::FaceHandle(f)].emission);
        }
        // A binary file's faces are placed by number.
        EXPECT_EQ(source_line_prop(binary)[OpenMesh::FaceHandle(1)], 2);
    }
}

TEST(PlyReader, FloatsAreTheirShortestDecimals) {
    // 0.1f is 0.100000001490116...; read as 0.1, as an OBJ of the same model says.
    SceneFiles files;
    std::string text =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    const float xyz[9] = {0.1f, 0, 0, 1, 0, 0, 0, 0.3f, 0};
    text.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const std::int32_t corners[3] = {0, 1, 2};
    text += char(3);
    text.append(reinterpret_cast<const char*>(corners), sizeof corners);
    LoadOptions options;
    options.default_material = Material{"default", {0.5, 0.5, 0.5}, {1, 1, 1}};
    PatchMesh mesh = load_mesh(files.write("scene.ply", text), options).mesh;
    bool found = false;
    for (auto v : mesh.vertices()) {
        if (mesh.point(v)[1] != 0) {
            EXPECT_EQ(mesh.point(v)[1], 0.3);
        }
        found = found || mesh.point(v)[0] == 0.1;
    }
    EXPECT_TRUE(found);
}

TEST(PlyReader, WithoutColoursFacesTakeTheDefaultMaterialOrAreRefused) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_EQ(ply_error(text),
              "scene.ply:13: face has no material (the PLY has no colour or "
              "emission properties)");
    SceneFiles files;
    LoadOptions options;
    options.default_material = Material{"default", {0.25, 0.5, 0.75}, {2, 2, 2}};
    PatchMesh mesh = load_mesh(files.write("plain.ply", text), options).mesh;
    EXPECT_EQ(FaceMaterials(mesh)[OpenMesh::FaceHandle(0)].reflectance,
              OpenMesh::Vec3d(0.25, 0.5, 0.75));
}

TEST(PlyReader, PolygonsAreRepairedUnlessStrict) {
    // A pentagon: triangulated by the repairs, refused by --strict.
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        "property float emission_red\nproperty float emission_green\n"
        "property float emission_blue\nend_header\n"
        "0 0 0\n1 0 0\n1.5 1 0\n0.5 2 0\n-0.5 1 0\n5 0 1 2 3 4 1 1 1\n";
    SceneFiles files;
    MeshFile repaired = load_mesh(files.write("scene.ply", text));
    EXPECT_EQ(repaired.mesh.n_faces(), 3u);
    EXPECT_EQ(repaired.repairs.total(), 1u);
    EXPECT_TRUE(contains(ply_error(text, true), "scene.ply:18: "));
}

// Errors at their place: what, and where.
TEST(PlyReader, BadFilesAreRefusedAtTheirLine) {
    const std::string end = "property float emission_green\nproperty float emission_blue\n";
    const struct {
        std::string text, message;
    } cases[] = {
        {"solid cube\n", "scene.ply:1: not a PLY file: its first line is not 'ply'"},
        {"ply\nformat ascii 2.0\n", "scene.ply:2: the format line must end in '1.0'"},
        {"ply\nformat utf8 1.0\n",
         "scene.ply:2: unknown PLY format 'utf8': hmcr reads ascii, binary_little_endian and "
         "binary_big_endian"},
        {"ply\nformat ascii 1.0\nelement vertex 3\n",
         "scene.ply:3: the header has no 'end_header'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n",
         "scene.ply:4: unknown property type 'quad'"},
        {"ply\nformat ascii 1.0\nelement vertex -1\n",
         "scene.ply:3: element count '-1' is not a non-negative integer"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\n",
         "scene.ply:5: element 'vertex' has a second property 'x'"},
        {ply_quads(end + "end_header\n", " 7"),
         "scene.ply:24: more values than the header's properties"},
        {ply_quads(end + "end_header\n", "").substr(0, kPlyQuads.size() - 4) + "\n",
         "scene.ply:24: fewer values than the header's properties"},
        {ply_quads(end + "end_header\n", "").replace(kPlyQuads.size() - 20, 1, "9"),
         "scene.ply:24: vertex index 9 is out of range (6 vertices)"},
        {ply_quads(end + "end_header\n", "").replace(kPlyQuads.size() - 14, 3, "256"),
         "scene.ply:24: '256' is not a value of type uchar"},
        {ply_quads(end + "end_header\n", "").replace(kPlyQuads.size() - 6, 1, "nan"),
         "scene.ply:24: 'nan' is not a finite number"},
        {ply_quads("property float emission_green\nend_header\n", ""),
         "scene.ply:8: element 'face' has 2 of the properties emission_red, emission_green, "
         "emission_blue: a colour needs all three"},
        {ply_quads(end + "end_header\n", "").replace(kPlyQuads.find("uchar red"), 5, "short"),
         "scene.ply:8: property 'red' of element 'face' is short: hmcr reads uchar (0-255), "
         "float or double (0-1)"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
         "scene.ply:1: the header has no element 'face' (a point cloud has no polygons)"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0\n1 0\n0 1\n3 0 1 2\n",
         "scene.ply:3: element 'vertex' needs a property 'z'"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
         "scene.ply:13: polygon with 2 vertices: a face needs 3"},
    };
    for (const auto& c : cases) EXPECT_EQ(ply_error(c.text), c.message) << c.text;
}

TEST(PlyReader, BinaryErrorsNameTheFace) {
    std::string text = binary_ply_quads(false);
    text.replace(text.find("ascii"), 5, "binary_little_endian");
    EXPECT_EQ(ply_error(text.substr(0, text.size() - 3)),
              "scene.ply: face 2: the file ends before the header's last element");
    std::string bad = text;
    bad[bad.size() - 27] = 9;  // the second face's second corner (its low byte)
    EXPECT_EQ(ply_error(bad), "scene.ply: face 2: vertex index 9 is out of range (6 vertices)");
}

// A header of a few lines may declare any count: it is refused before anything is allocated.
TEST(PlyReader, CountsTheFileCannotHoldAreRefusedBeforeAllocation) {
    const std::string header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1000000000000\n"
        "property list uchar int vertex_indices\nend_header\n";
    const std::string data(3 * 12, '\0');
    EXPECT_EQ(ply_error(header + data),
              "scene.ply:7: element 'face' declares 1000000000000 instances, more than the 36 "
              "bytes after the header hold");
    std::string ascii = header;
    ascii.replace(ascii.find("binary_little_endian"), 20, "ascii");
    ascii.replace(ascii.find("1000000000000"), 13, "200000000");
    EXPECT_EQ(ply_error(ascii + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "scene.ply:7: element 'face' declares 200000000 instances, more than the 26 bytes "
              "after the header hold");
}

}  // namespace
}  // namespace hmcr
