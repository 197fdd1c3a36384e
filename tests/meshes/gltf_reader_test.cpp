// SPDX-License-Identifier: Apache-2.0
// read_gltf through load_mesh: a quad split as a fan is one quad again, materials come from the
// factors (base colour, metallic, emissive strength, doubleSided), nodes place and turn meshes;
// .glb reads as .gltf; bad and hostile files are refused with one line naming the file and the
// part of it.
#include "meshes/gltf_reader.h"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <numbers>

#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using nlohmann::json;
using test::contains;
using test::scene_error;
using test::SceneFiles;

// Four corners and the fan (0 1 2)(0 2 3): float positions, then unsigned short indices.
std::string quad_bytes(float lift = 0) {
    const float xyz[12] = {0, 0, 0, 1, 0, 0, 1, 1, lift, 0, 1, 0};
    const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    std::string bytes(sizeof xyz + sizeof indices, '\0');
    std::memcpy(bytes.data(), xyz, sizeof xyz);
    std::memcpy(bytes.data() + sizeof xyz, indices, sizeof indices);
    return bytes;
}

// A glTF of one node and one mesh of one primitive on quad_bytes() in buffer "mesh.bin".
json quad_gltf() {
    return {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
        {"materials",
         {{{"name", "lamp"},
           {"pbrMetallicRoughness",
            {{"baseColorFactor", {0.5, 0.25, 0.75, 1}}, {"metallicFactor", 0}}},
           {"emissiveFactor", {0.5, 0.25, 1}},
           {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}}}},
        {"buffers", {{{"byteLength", 60}, {"uri", "mesh.bin"}}}},
    };
}

MeshFile load_gltf(SceneFiles& files, const json& gltf, const std::string& bytes = quad_bytes(),
                   const LoadOptions& options = {}) {
    files.write("mesh.bin", bytes);
    return load_mesh(files.write("scene.gltf", gltf.dump()), options);
}

// The message of loading the glTF, its folder left out.
std::string gltf_error(const json& gltf, const std::string& bytes = quad_bytes()) {
    SceneFiles files;
    std::string message = scene_error([&] { load_gltf(files, gltf, bytes); });
    const std::string folder = files.path().string() + "/";
    if (message.rfind(folder, 0) == 0) message.erase(0, folder.size());
    return message;
}

TEST(GltfReader, AQuadSplitAsAFanIsOneQuadWithTheFactorsMaterial) {
    SceneFiles files;
    MeshFile file = load_gltf(files, quad_gltf());
    PatchMesh& mesh = file.mesh;
    ASSERT_EQ(mesh.n_faces(), 1u);
    const OpenMesh::FaceHandle f(0);
    EXPECT_EQ(mesh.valence(f), 4u);
    const FaceMaterials material(mesh);
    EXPECT_EQ(material[f].reflectance, OpenMesh::Vec3d(0.5, 0.25, 0.75));
    EXPECT_EQ(material[f].emission, OpenMesh::Vec3d(2, 1, 4) * std::numbers::pi);
    EXPECT_EQ(material.back_index(f), kOneSided);  // doubleSided is false
    EXPECT_EQ(source_line_prop(mesh)[f], 1);       // face 1
    EXPECT_TRUE(file.warnings.empty());
}

TEST(GltfReader, ANonPlanarPairStaysTwoTriangles) {
    SceneFiles files;
    // The third corner 0.5 above the plane of the others.
    EXPECT_EQ(load_gltf(files, quad_gltf(), quad_bytes(0.5f)).mesh.n_faces(), 2u);
}

TEST(GltfReader, DoubleSidedMaterialsAreTwoSided) {
    json gltf = quad_gltf();
    gltf["materials"][0]["doubleSided"] = true;
    SceneFiles files;
    PatchMesh mesh = load_gltf(files, gltf).mesh;
    EXPECT_NE(FaceMaterials(mesh).back_index(OpenMesh::FaceHandle(0)), kOneSided);
}

TEST(GltfReader, TheMetalPartIsAbsorbedWithAWarning) {
    json gltf = quad_gltf();
    gltf["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.5;
    gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    SceneFiles files;
    MeshFile file = load_gltf(files, gltf);
    EXPECT_EQ(FaceMaterials(file.mesh)[OpenMesh::FaceHandle(0)].reflectance,
              OpenMesh::Vec3d(0.25, 0.125, 0.375));
    ASSERT_EQ(file.warnings.size(), 2u);
    EXPECT_TRUE(
        contains(file.warnings[0], "scene.gltf: materials[0] ('lamp'): metallicFactor 0.5"));
    EXPECT_TRUE(contains(file.warnings[1], "baseColorTexture ignored: hmcr reads the factors"));
}

TEST(GltfReader, NodesPlaceMeshesAndAMirrorKeepsTheFront) {
    json gltf = quad_gltf();
    gltf["nodes"] = {{{"children", {1}}, {"translation", {0, 0, 2}}},
                     {{"mesh", 0}, {"scale", {-1, 1, 1}}}};
    SceneFiles files;
    PatchMesh mesh = load_gltf(files, gltf).mesh;
    ASSERT_EQ(mesh.n_faces(), 1u);
    for (auto v : mesh.vertices()) {
        EXPECT_LE(mesh.point(v)[0], 0);
        EXPECT_EQ(mesh.point(v)[2], 2);
    }
    // The quad faces +z in the file; mirrored in x it still does.
    EXPECT_GT(mesh.calc_face_normal(OpenMesh::FaceHandle(0))[2], 0);
}

// The GLB container of the glTF, its buffer the BIN chunk.
std::string glb(json gltf, const std::string& bin) {
    gltf["buffers"][0].erase("uri");
    std::string text = gltf.dump();
    text.append((4 - text.size() % 4) % 4, ' ');
    const auto word = [](std::uint32_t x) { return std::string(reinterpret_cast<char*>(&x), 4); };
    return "glTF" + word(2) + word(std::uint32_t(12 + 8 + text.size() + 8 + bin.size())) +
           word(std::uint32_t(text.size())) + "JSON" + text + word(std::uint32_t(bin.size())) +
           std::string("BIN\0", 4) + bin;
}

TEST(GltfReader, GlbReadsAsGltf) {
    SceneFiles files;
    PatchMesh from_gltf = load_gltf(files, quad_gltf()).mesh;
    PatchMesh from_glb = load_mesh(files.write("scene.glb", glb(quad_gltf(), quad_bytes()))).mesh;
    EXPECT_EQ(geometry_hash(from_glb), geometry_hash(from_gltf));
    EXPECT_EQ(FaceMaterials(from_glb).table()[0].emission,
              FaceMaterials(from_gltf).table()[0].emission);
}

TEST(GltfReader, APrimitiveWithoutMaterialTakesTheDefaultOrIsRefused) {
    json gltf = quad_gltf();
    gltf["meshes"][0]["primitives"][0].erase("material");
    EXPECT_EQ(gltf_error(gltf),
              "scene.gltf: face 1: face has no material (its primitive has no material)");
    SceneFiles files;
    LoadOptions options;
    options.default_material = Material{"default", {0.25, 0.5, 0.75}, {1, 1, 1}};
    PatchMesh mesh = load_gltf(files, gltf, quad_bytes(), options).mesh;
    EXPECT_EQ(FaceMaterials(mesh)[OpenMesh::FaceHandle(0)].reflectance,
              OpenMesh::Vec3d(0.25, 0.5, 0.75));
}

TEST(GltfReader, BadFilesAreRefusedNamingTheirPart) {
    const auto with = [](const json::json_pointer& at, const json& value) {
        json gltf = quad_gltf();
        gltf[at] = value;
        return gltf;
    };
    const struct {
        json gltf;
        std::string message;
    } cases[] = {
        // A count that would ask for terabytes is refused before anything is read.
        {with("/accessors/0/count"_json_pointer, 1000000000000),
         "scene.gltf: accessors[0]: its elements do not lie in its buffer view and buffer"},
        {with("/bufferViews/1/byteOffset"_json_pointer, 50),
         "scene.gltf: accessors[1]: its elements do not lie in its buffer view and buffer"},
        {with("/accessors/0/componentType"_json_pointer, 5123),
         "scene.gltf: accessors[0]: POSITION must be float"},
        {with("/accessors/1"_json_pointer,
              {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "VEC2"}}),
         "scene.gltf: accessors[1]: has the wrong type for meshes[0].primitives[0] indices"},
        {with("/accessors/1/count"_json_pointer, 5),
         "scene.gltf: meshes[0].primitives[0]: 5 indices are not triangles"},
        {with("/meshes/0/primitives/0/material"_json_pointer, 3),
         "scene.gltf: meshes[0].primitives[0]: material 3 does not exist"},
        {with("/nodes"_json_pointer, {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}}),
         "scene.gltf: nodes[0]: is reached twice: a node has one parent"},
        {with("/nodes/0/matrix"_json_pointer, {1, 0, 0}),
         "scene.gltf: nodes[0]: matrix needs 16 numbers"},
        {with("/extensionsRequired"_json_pointer, {"KHR_draco_mesh_compression"}),
         "scene.gltf: requires the extension 'KHR_draco_mesh_compression', which hmcr does not "
         "read"},
        {with(
             "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength"_json_pointer,
             -1),
         "scene.gltf: materials[0]: KHR_materials_emissive_strength: emissiveStrength must be a "
         "number of at least 0"},
        // TinyGLTF's own check, in its words.
        {with("/materials/0/emissiveFactor"_json_pointer, {1, 1}),
         "scene.gltf: Array length of `emissiveFactor` parameter in material must be 3, but got "
         "2"},
    };
    for (const auto& c : cases) EXPECT_EQ(gltf_error(c.gltf), c.message) << c.gltf.dump();
}

TEST(GltfReader, IndicesOutOfRangeAreRefused) {
    std::string bytes = quad_bytes();
    bytes[48 + 2] = 7;  // the second index
    EXPECT_EQ(gltf_error(quad_gltf(), bytes),
              "scene.gltf: accessors[1]: index 7 is out of range (4 vertices)");
}

// Nodes that place one mesh many times are counted before anything is read.
TEST(GltfReader, PlacingMoreThanTheLimitIsRefusedBeforeReading) {
    json gltf = quad_gltf();
    gltf["nodes"] = json::array();
    for (int k = 0; k < 6; ++k) gltf["nodes"].push_back({{"mesh", 0}});
    gltf["scenes"][0]["nodes"] = {0, 1, 2, 3, 4, 5};
    SceneFiles files;
    files.write("mesh.bin", quad_bytes());
    const auto path = files.write("scene.gltf", gltf.dump());
    GltfOptions options;
    options.max_polygons = 12;  // the six quads' twelve triangles pass
    EXPECT_EQ(read_gltf(path, options).polygon_count(), 6u);
    options.max_polygons = 11;
    EXPECT_EQ(scene_error([&] { read_gltf(path, options); }),
              path.string() +
                  ": its nodes place more than 11 triangles or 33 vertices: hmcr "
                  "reads no more");
}

// What TinyGLTF refuses is one line naming the file.
TEST(GltfReader, WhatTheParserRefusesIsOneLine) {
    json short_buffer = quad_gltf();
    short_buffer["buffers"][0]["byteLength"] = 600;
    json missing = quad_gltf();
    missing["buffers"][0]["uri"] = "elsewhere.bin";
    for (const json& gltf : {short_buffer, missing}) {
        const std::string message = gltf_error(gltf);
        EXPECT_EQ(message.rfind("scene.gltf: ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    SceneFiles files;
    const auto truncated = files.write("cut.glb", glb(quad_gltf(), quad_bytes()).substr(0, 40));
    EXPECT_TRUE(contains(scene_error([&] { load_mesh(truncated); }), "cut.glb: "));
    const auto text = files.write("bad.gltf", "{\"asset\": ");
    EXPECT_TRUE(contains(scene_error([&] { load_mesh(text); }), "bad.gltf: "));
}

}  // namespace
}  // namespace hmcr
