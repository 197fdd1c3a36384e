// SPDX-License-Identifier: Apache-2.0
// Bad and hostile PLY and glTF files through the command line: one line naming the file and the
// place, exit code 2, nothing written; headers and counts that ask for terabytes are refused
// at once.
#include <string>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

constexpr const char* kPlyTriangleHeader =
    "ply\n"
    "format ascii 1.0\n"
    "element vertex 3\n"
    "property float x\n"
    "property float y\n"
    "property float z\n";

TEST_F(Hostile, BadPlyFilesAreRefusedWithTheirLine) {
    const std::string faces =
        "element face 1\nproperty list uchar int vertex_indices\n"
        "property float emission_red\nproperty float emission_green\n"
        "property float emission_blue\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    const struct {
        std::string text, needle;
    } cases[] = {
        {std::string(kPlyTriangleHeader) + faces + "3 0 1 7 1 1 1\n",
         "bad.ply:16: vertex index 7 is out of range (3 vertices)"},
        {std::string(kPlyTriangleHeader) + faces + "3 0 1 2 1 1 -1\n",
         "bad.ply:16: emission -1 of material 'colour 1' is negative"},
        {std::string(kPlyTriangleHeader) + "element face 1000000000000\n" +
             "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
         "bad.ply:7: element 'face' declares 1000000000000 instances"},
        {"ply\nformat binary_little_endian 1.0\n" + std::string(kPlyTriangleHeader).substr(21) +
             faces.substr(0, faces.find("0 0 0")) + std::string(20, '\0'),
         "bad.ply:"},
    };
    for (const auto& c : cases) {
        m_temp.write("bad.ply", c.text);
        refused("solve bad.ply -o out.vtp", c.needle);
    }
}

TEST_F(Hostile, BadGltfFilesAreRefusedNamingTheirPart) {
    const std::string asset = R"("asset": {"version": "2.0"})";
    const struct {
        std::string text, needle;
    } cases[] = {
        {"{" + asset + R"(, "buffers": [{"byteLength": 1000000000000, "uri": "/dev/zero"}]})",
         "bad.gltf: "},
        {"{" + asset + R"(, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 4}]})",
         "bad.gltf: mesh 4 does not exist"},
        {"{" + asset + R"(, "extensionsRequired": ["KHR_draco_mesh_compression"]})",
         "bad.gltf: requires the extension 'KHR_draco_mesh_compression'"},
        {"{" + asset + ", ", "bad.gltf: "},
    };
    for (const auto& c : cases) {
        m_temp.write("bad.gltf", c.text);
        refused("solve bad.gltf -o out.vtp", c.needle);
    }
    m_temp.write("bad.glb", std::string("glTF\2\0\0\0", 8) + std::string(4, '\xff'));
    refused("solve bad.glb -o out.vtp", "bad.glb: ");
}

}  // namespace
}  // namespace hmcr::test
