// SPDX-License-Identifier: Apache-2.0
// Specular reflectance as the readers take it (docs/design.md §1.2, §11.2, §11.3): MTL `Ks`
// with `illum 3` a mirror, MGF `rs` with its roughness; Kd + Ks checked like Kd; unsupported
// illumination models and bad roughness refused at their line.
#include <gtest/gtest.h>

#include "meshes/mgf_color.h"
#include "meshes/mgf_reader.h"
#include "meshes/obj_reader.h"
#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr::specular_materials {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

// A triangle of material `m` (lines 1-5) and a light, so that the scene solves.
constexpr const char* kObj =
    "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n"
    "v 0 0 1\nv 0 1 1\nv 1 0 1\nusemtl light\nf 4 5 6\n";
constexpr const char* kLight = "newmtl light\nKe 1 1 1\n";

PatchMesh load(const std::string& mtl, bool strict = false) {
    SceneFiles files;
    files.write("scene.mtl", mtl + kLight);
    LoadOptions options;
    options.strict = strict;
    return load_obj(files.write("scene.obj", kObj), options);
}

std::string load_error(const std::string& mtl, bool strict = false) {
    return scene_error([&] { load(mtl, strict); });
}

FaceMaterial first_face(const PatchMesh& mesh) {
    return FaceMaterials(mesh)[OpenMesh::FaceHandle(0)];
}

TEST(SpecularMaterials, MtlKsWithIllum3IsAMirrorInEitherOrder) {
    for (const std::string mtl : {"newmtl m\nKd 0.1 0.1 0.1\nKs 0.8 0.7 0.6\nillum 3\n",
                                  "newmtl m\nillum 3\nKs 0.8 0.7 0.6\nKd 0.1 0.1 0.1\n"}) {
        const FaceMaterial m = first_face(load(mtl));
        EXPECT_EQ(m.reflectance, OpenMesh::Vec3d(0.1, 0.1, 0.1));
        EXPECT_EQ(m.specular, OpenMesh::Vec3d(0.8, 0.7, 0.6));
        EXPECT_EQ(m.roughness, 0);
    }
}

// illum 0 to 2 leave Ks unused (2's highlight is not modelled), as does a material without
// illum; Blender writes `Ks 0.5 0.5 0.5` and `illum 2` for every material.
TEST(SpecularMaterials, MtlKsWithoutIllum3IsNotUsed) {
    for (const std::string illum : {"", "illum 0\n", "illum 1\n", "illum 2\n"}) {
        const FaceMaterial m =
            first_face(load("newmtl m\nKd 0.6 0.6 0.6\nKs 0.5 0.5 0.5\n" + illum));
        EXPECT_EQ(m.specular, OpenMesh::Vec3d(0, 0, 0)) << illum;
    }
}

TEST(SpecularMaterials, MtlUnsupportedIllumIsRefusedAtItsLine) {
    for (const std::string model : {"4", "5", "7", "10", "3.5", "-1"}) {
        EXPECT_TRUE(contains(load_error("newmtl m\nKd 0.5 0.5 0.5\nillum " + model + "\n"),
                             "scene.mtl:3: illum " + model +
                                 " is not supported: hmcr reads illum "
                                 "0, 1 and 2 (diffuse; Ks unused) and 3 (Ks an ideal mirror)"));
    }
    EXPECT_TRUE(contains(load_error("newmtl m\nillum\n"), "scene.mtl:2: 'illum' needs one number"));
    EXPECT_TRUE(
        contains(load_error("newmtl m\nillum 3 3\n"), "scene.mtl:2: 'illum' needs one number"));
    EXPECT_TRUE(contains(load_error("newmtl m\nKs 0.5 0.5\n"),
                         "scene.mtl:2: 'Ks' needs three numbers (r g b)"));
}

// Kd + Ks above 1 is an error at the Ks line; 1 itself is accepted with a warning (a repair,
// refused by --strict), as Kd = 1 is.
TEST(SpecularMaterials, MtlKdPlusKsAboveOneIsRefused) {
    const std::string over = "newmtl m\nKd 0.5 0.5 0.5\nillum 3\nKs 0.4 0.6 0.4\n";
    EXPECT_TRUE(contains(load_error(over),
                         "scene.mtl:4: diffuse + specular reflectance 1.1 of "
                         "material 'm' is above 1"));
    const std::string one = "newmtl m\nKd 0.5 0.5 0.5\nillum 3\nKs 0.5 0.5 0.5\n";
    EXPECT_TRUE(contains(load_error(one, true),
                         "scene.mtl:4: diffuse + specular reflectance 1 of "
                         "material 'm' is not below 1"));
    EXPECT_EQ(first_face(load(one)).specular, OpenMesh::Vec3d(0.5, 0.5, 0.5));
    EXPECT_TRUE(contains(load_error("newmtl m\nillum 3\nKs 0.5 -0.1 0.5\n"),
                         "scene.mtl:3: specular reflectance -0.1 of material 'm' is negative"));
    // Without illum 3 Ks is not the surface's: no check.
    EXPECT_EQ(first_face(load("newmtl m\nKd 0.9 0.9 0.9\nKs 0.9 0.9 0.9\n")).specular,
              OpenMesh::Vec3d(0, 0, 0));
}

// MGF: a unit square of material m, and a light above it.
std::string mgf(const std::string& material) {
    return "m light =\n ed 10\nv a =\n p 0 0 1\nv b =\n p 0 1 1\nv c =\n p 1 0 1\nf a b c\n"
           "m m =\n" +
           material +
           "v q0 =\n p 0 0 0\nv q1 =\n p 1 0 0\nv q2 =\n p 1 1 0\nv q3 =\n p 0 1 0\n"
           "f q0 q1 q2 q3\n";
}

MeshFile load_mgf(const std::string& text, bool strict = false) {
    SceneFiles files;
    LoadOptions options;
    options.strict = strict;
    return load_mesh(files.write("scene.mgf", text), options);
}

FaceMaterial square(const MeshFile& f) { return FaceMaterials(f.mesh)[OpenMesh::FaceHandle(1)]; }

TEST(SpecularMaterials, MgfRsSetsTheSpecularReflectanceAndItsRoughness) {
    const MeshFile glossy = load_mgf(mgf(" rd 0.1\n rs 0.5 0.1\n"));
    EXPECT_EQ(square(glossy).specular, OpenMesh::Vec3d(0.5, 0.5, 0.5));
    EXPECT_EQ(square(glossy).roughness, 0.1);
    EXPECT_EQ(square(glossy).reflectance, OpenMesh::Vec3d(0.1, 0.1, 0.1));
    const MeshFile mirror = load_mgf(mgf(" rs 0.9 0\n"));
    EXPECT_EQ(square(mirror).specular, OpenMesh::Vec3d(0.9, 0.9, 0.9));
    EXPECT_EQ(square(mirror).roughness, 0);
    // rs is no longer among the entities the reader skips
    for (const std::string& w : glossy.warnings) EXPECT_FALSE(contains(w, "rs 1 time")) << w;
}

TEST(SpecularMaterials, MgfBadRsIsRefusedAtItsLine) {
    const auto error = [&](const std::string& material) {
        return scene_error([&] { load_mgf(mgf(material)); });
    };
    // the material's statements start on line 11
    EXPECT_TRUE(contains(error(" rs 0.5 -0.1\n"),
                         "scene.mgf:11: rs roughness -0.1 is not in [0, 1] (0: a mirror)"));
    EXPECT_TRUE(
        contains(error(" rs 0.5 1.5\n"), "scene.mgf:11: rs roughness 1.5 is not in [0, 1]"));
    EXPECT_TRUE(contains(error(" rs -0.5 0\n"), "scene.mgf:11: rs -0.5 is not in [0, 1]"));
    EXPECT_TRUE(contains(error(" rs 0.5\n"), "scene.mgf:11:"));
}

// rd + rs above 1 (RenderPark's cube: a yellow rd 0.9 under rs 0.2) is repaired by a smaller
// rs, the sum's largest channel 0.99, rd kept; a strict load refuses it at the rs line.
TEST(SpecularMaterials, MgfRdPlusRsAbove1GetsASmallerRs) {
    const std::string text = mgf(" rd 0.6\n rs 0.5 0.05\n");
    const MeshFile file = load_mgf(text);
    EXPECT_EQ(square(file).reflectance, OpenMesh::Vec3d(0.6, 0.6, 0.6));
    EXPECT_NEAR(square(file).specular[0], 0.39, 1e-12);
    EXPECT_EQ(square(file).roughness, 0.05);
    EXPECT_EQ(file.repairs[RepairKind::specular_reduced].count, 1u);
    EXPECT_EQ(file.repairs[RepairKind::specular_reduced].first.substr(
                  file.repairs[RepairKind::specular_reduced].first.size() - 12),
              "scene.mgf:12");
    EXPECT_TRUE(contains(scene_error([&] { load_mgf(text, true); }),
                         "scene.mgf:12: diffuse + specular reflectance 1.1 of material 'm' is "
                         "not below 1"));
    // A red rd whose channel alone is 0.99 leaves its rs no room in that channel.
    const MeshFile red = load_mgf(mgf(" c\n  cxy 0.7 0.3\n rd 0.5\n c\n rs 0.6 0\n"));
    EXPECT_LE((square(red).reflectance + square(red).specular).max(), 0.99 + 1e-12);
    EXPECT_EQ(square(red).specular, OpenMesh::Vec3d(0, 0, 0));
}

double luminance(const OpenMesh::Vec3d& c) { return rgb_luminance({c[0], c[1], c[2]}); }

// MGF states rd and rs as luminances, which the specification lets sum to 1. A saturated colour
// of a modest luminance has a channel near 1 (RenderPark's hospital: a red rd 0.29 under a
// white rs 0.29), and a grey written as cxy 0.333333 0.333333 is a hair off white (its cube:
// rd 0.6, rs 0.4): both fit once their colours move toward grey, keeping their luminances.
TEST(SpecularMaterials, MgfRdPlusRsOfALuminanceUpTo1FitsTowardGrey) {
    const MeshFile red = load_mgf(mgf(" c\n  cxy 0.75 0.1\n rd 0.29\n c\n rs 0.29 0.05\n"));
    const FaceMaterial m = square(red);
    EXPECT_LE((m.reflectance + m.specular).max(), 0.99 + 1e-12);
    EXPECT_NEAR(luminance(m.reflectance), 0.29, 1e-12);
    EXPECT_NEAR(luminance(m.specular), 0.29, 1e-12);
    EXPECT_GT(m.reflectance[0], 2 * m.reflectance[1]);  // still red
    EXPECT_EQ(red.repairs.total(), 0u);
    const MeshFile grey = load_mgf(mgf(" c\n  cxy 0.333333 0.333333\n rd 0.6\n rs 0.4 0.01\n"));
    EXPECT_EQ(square(grey).reflectance + square(grey).specular, OpenMesh::Vec3d(1, 1, 1));
    EXPECT_EQ(grey.repairs[RepairKind::reflectance_one].count, 1u);  // it absorbs nothing
}

}  // namespace
}  // namespace hmcr::specular_materials
