// SPDX-License-Identifier: Apache-2.0
// Where a patch's back comes from (docs/design.md §1.3, §1.6, §1.7): a material's sides (MGF's
// `sides`, the load's setting for OBJ, a scene file's per material), and coincident faces. The
// MGF files reproduce the statement patterns of RenderPark's scenes: materials that do not say
// their sides, a thin wall written as two faces facing away from each other in two materials, a
// material defined again with the same values, and a face on another's corners in another
// material.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"
#include "tests/support/thin_walls.h"

namespace hmcr::sides_test {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

constexpr const char* kMtl =
    "newmtl paper\nKd 0.5 0.5 0.5\n"
    "newmtl Light Panel\nKd 0 0 0\nKe 1 1 1\n";

// A sheet of paper at z = 0 facing up (line 6) under a panel facing down (line 11).
constexpr const char* kObj =
    "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl paper\nf 1 2 3\n"
    "v 0 0 1\nv 0 1 1\nv 1 1 1\nusemtl Light Panel\nf 4 5 6\n";

// The material table's index of each face's back (kOneSided for none); empty for a mesh without
// the property.
std::vector<std::uint32_t> backs(const PatchMesh& mesh) {
    OpenMesh::FPropHandleT<std::uint32_t> h;
    if (!mesh.get_property_handle(h, kBackMaterialProp)) return {};
    const FaceMaterials m(mesh);
    std::vector<std::uint32_t> out;
    for (auto f : mesh.faces()) out.push_back(m.back_index(f));
    return out;
}

std::vector<std::uint32_t> fronts(const PatchMesh& mesh) {
    const FaceMaterials m(mesh);
    std::vector<std::uint32_t> out;
    for (auto f : mesh.faces()) out.push_back(m.index(f));
    return out;
}

MeshFile load(SceneFiles& files, const std::string& name, const LoadOptions& options = {}) {
    return load_mesh(files.path() / name, options);
}

TEST(Sides, ObjFacesAreTwoSidedUnlessTheLoadSaysOne) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    files.write("scene.obj", kObj);
    const MeshFile two = load(files, "scene.obj");
    EXPECT_EQ(backs(two.mesh), fronts(two.mesh));  // each back in its face's material
    LoadOptions one_sided;
    one_sided.sides = 1;
    EXPECT_TRUE(backs(load(files, "scene.obj", one_sided).mesh).empty());  // no property at all
}

TEST(Sides, AMaterialsSidesByNameWinAndAnUnknownNameIsAnError) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    files.write("scene.obj", kObj);
    LoadOptions options;
    options.sides = 1;
    options.material_sides = {{{"paper", 2}}, "scene.json: material_sides"};
    const MeshFile file = load(files, "scene.obj", options);
    EXPECT_EQ(backs(file.mesh), (std::vector<std::uint32_t>{fronts(file.mesh)[0], kOneSided}));
    options.material_sides = {{{"Light Panel", 2}, {"papr", 1}}, "scene.json: material_sides"};
    EXPECT_TRUE(contains(scene_error([&] { load(files, "scene.obj", options); }),
                         "scene.json: material_sides: no material 'papr' in the mesh"));
}

TEST(Sides, SceneFileKeysAndTheCommandLineOverThem) {
    SceneFiles files;
    files.write("scene.mtl", kMtl);
    files.write("scene.obj", kObj);
    const auto json = files.write(
        "scene.json", R"({"mesh": "scene.obj", "sides": 1, "material_sides": {"Light Panel": 2}})");
    const Scene scene = load_scene(json.string());
    EXPECT_EQ(backs(scene.mesh), (std::vector<std::uint32_t>{kOneSided, fronts(scene.mesh)[1]}));
    LoadOptions two;
    two.sides = 2;
    const Scene both = load_scene(json.string(), two);
    EXPECT_EQ(backs(both.mesh), fronts(both.mesh));
    for (const char* bad : {R"("sides": 3)", R"("sides": "2")", R"("sides": 1.5)"}) {
        const auto file =
            files.write("bad.json", std::string(R"({"mesh": "scene.obj", )") + bad + "}");
        EXPECT_TRUE(contains(scene_error([&] { load_scene(file.string()); }),
                             "bad.json: sides: must be 1 or 2"))
            << bad;
    }
    const auto file =
        files.write("bad.json", R"({"mesh": "scene.obj", "material_sides": {"paper": 0}})");
    EXPECT_TRUE(contains(scene_error([&] { load_scene(file.string()); }),
                         "bad.json: material_sides: 'paper': must be 1 or 2"));
}

// A lamp (line 3) that does not say its sides, a one-sided floor (lines 5-7).
constexpr const char* kMgfHead =
    "m lamp =\n ed 100\n"
    "m floor =\n rd 0.5\n sides 1\n"
    "v a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 1 1 0\nv d =\n p 0 1 0\n";  // lines 6-13

TEST(Sides, MgfMaterialsAreTwoSidedUnlessTheySayOne) {
    SceneFiles files;
    files.write("scene.mgf", std::string(kMgfHead) + "m lamp\nf a b c\nm floor\nf a c d\n");
    const MeshFile file = load(files, "scene.mgf");
    const FaceMaterials m(file.mesh);
    const auto b = backs(file.mesh);
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0], m.index(OpenMesh::FaceHandle(0)));  // the lamp's back emits as its front
    EXPECT_EQ(m.table()[b[0]].emission[0], 100);
    EXPECT_EQ(b[1], kOneSided);
    LoadOptions one_sided;  // RenderPark's default, all one-sided
    one_sided.sides = 1;
    EXPECT_TRUE(backs(load(files, "scene.mgf", one_sided).mesh).empty());
}

// A thin wall of two materials, written as two faces facing away from each other (as the
// hospital's structure.mgf has it), and the same material defined twice with the same values
// around a copy of a face (as classroom.mgf has it).
TEST(Sides, CoincidentFacesFacingAwayAreOneTwoSidedPatch) {
    SceneFiles files;
    files.write("scene.mgf", std::string(kMgfHead) +
                                 "m red =\n rd 0.3\n sides 1\nf a b c d\n"  // 14-17
                                 "m floor\nf d c b a\n"                     // 18-19
                                 "m lamp\nv e =\n p 0 0 1\nf a b e\n"       // 20-23
                                 "m lamp =\n ed 100\nf b e a\n");           // 24-26
    const MeshFile file = load(files, "scene.mgf");
    ASSERT_EQ(file.mesh.n_faces(), 2u);
    const FaceMaterials m(file.mesh);
    const OpenMesh::FaceHandle wall(0);
    EXPECT_EQ(m[wall].reflectance[0], 0.3);                        // red in front
    EXPECT_EQ(m.table()[m.back_index(wall)].reflectance[0], 0.5);  // the floor's behind
    EXPECT_TRUE(contains(file.repairs[RepairKind::sides_joined].first, "scene.mgf:19"));
    EXPECT_TRUE(contains(file.repairs[RepairKind::duplicate_dropped].first, "scene.mgf:26"));
    EXPECT_EQ(file.repairs.total(), 2u);
    // A strict load joins them too, and refuses the copy.
    LoadOptions strict;
    strict.strict = true;
    EXPECT_TRUE(contains(scene_error([&] { load(files, "scene.mgf", strict); }),
                         "scene.mgf:26: duplicate face"));
    files.write("strict.mgf", std::string(kMgfHead) +
                                  "m red =\n rd 0.3\n sides 1\nf a b c d\n"
                                  "m floor\nf d c b a\nm lamp\nv e =\n p 0 0 1\nf a b e\n");
    const MeshFile joined = load(files, "strict.mgf", strict);
    EXPECT_EQ(joined.mesh.n_faces(), 2u);
    EXPECT_EQ(joined.repairs[RepairKind::sides_joined].count, 1u);
    EXPECT_EQ(joined.repairs.total(), 1u);
}

// Each side is the material of the face that faces it, whatever backs the faces had.
TEST(Sides, EachSideIsTheMaterialOfTheFaceFacingIt) {
    SceneFiles files;
    files.write("scene.mgf", std::string(kMgfHead) +
                                 "m red =\n rd 0.3\nf a b c\n"   // two-sided
                                 "m blue =\n rd 0.2\nf c b a\n"  // two-sided
                                 "m lamp\nv e =\n p 0 0 1\nf a b e\n");
    const MeshFile file = load(files, "scene.mgf");
    const FaceMaterials m(file.mesh);
    const OpenMesh::FaceHandle f(0);
    EXPECT_EQ(m[f].reflectance[0], 0.3);
    EXPECT_EQ(m.table()[m.back_index(f)].reflectance[0], 0.2);
}

// A mirrored array whose instances share a face on the mirror plane (examp1.mgf's reflector):
// the two copies of that face face away from each other, one two-sided patch. And a face
// written again the same way in another material (graz.mgf's touching boxes): the first stays.
TEST(Sides, MirroredHalvesShareATwoSidedFaceAndAnotherMaterialLoses) {
    SceneFiles files;
    files.write("scene.mgf", std::string(kMgfHead) +
                                 "m floor\nxf -a 2 -my\nprism a b c d 1\nxf\n"  // 14-17
                                 "m lamp\nv e =\n p 0 0 3\nf a b e\n"           // 18-21
                                 "m red =\n rd 0.3\nf b e a\n");                // 22-24
    const MeshFile file = load(files, "scene.mgf");
    EXPECT_EQ(file.mesh.n_faces(), 2u * 6 - 1 + 1);
    EXPECT_EQ(file.repairs[RepairKind::sides_joined].count, 1u);
    EXPECT_TRUE(contains(file.repairs[RepairKind::sides_joined].first, "scene.mgf:16"));
    EXPECT_TRUE(contains(file.repairs[RepairKind::coincident_dropped].first, "scene.mgf:24"));
    const FaceMaterials m(file.mesh);
    EXPECT_EQ(m[OpenMesh::FaceHandle(int(file.mesh.n_faces()) - 1)].emission[0], 100);
}

TEST(Sides, AThirdFaceOnTheSameCornersIsAnError) {
    SceneFiles files;
    files.write("scene.mgf",
                std::string(kMgfHead) + "m floor\nf a b c\nf c b a\nm lamp\nf b c a\n");
    EXPECT_TRUE(contains(scene_error([&] { load(files, "scene.mgf"); }),
                         "scene.mgf:18: a third face on the same vertices as the faces on lines "
                         "15 and 16: a surface has two sides"));
    // Copies do not count: a face, its copy and its back are one two-sided patch.
    files.write("ok.mgf", std::string(kMgfHead) +
                              "m floor\nf a b c\nf b c a\nf c b a\n"
                              "m lamp\nv e =\n p 0 0 1\nf a b e\n");
    const MeshFile ok = load(files, "ok.mgf");
    EXPECT_EQ(ok.mesh.n_faces(), 2u);
    EXPECT_EQ(ok.repairs[RepairKind::duplicate_dropped].count, 1u);
    EXPECT_EQ(ok.repairs[RepairKind::sides_joined].count, 1u);
}

// The wall's faces (after the two lamps): each two-sided, paint (0.8) in front and tiles (0.3)
// behind, and their area.
double two_sided_wall_area(const MeshFile& file) {
    const FaceMaterials m(file.mesh);
    double area = 0;
    for (auto f : file.mesh.faces()) {
        if (f.idx() < 2) continue;
        EXPECT_EQ(m[f].reflectance[0], 0.8) << "face " << f.idx();
        EXPECT_NE(m.back_index(f), kOneSided) << "face " << f.idx();
        if (m.back_index(f) == kOneSided) continue;
        EXPECT_EQ(m.table()[m.back_index(f)].reflectance[0], 0.3) << "face " << f.idx();
        std::vector<Eigen::Vector3d> p;
        for (auto v : file.mesh.fv_range(f)) {
            const auto& q = file.mesh.point(v);
            p.emplace_back(q[0], q[1], q[2]);
        }
        for (std::size_t k = 1; k + 1 < p.size(); ++k)
            area += 0.5 * (p[k] - p[0]).cross(p[k + 1] - p[0]).norm();
    }
    return area;
}

// A thin wall of N corners written as two faces facing away from each other is one surface
// with two sides, whatever N and whichever corner each face starts from: the faces are
// compared as polygons, before they are cut into triangles (each cut its own way, their
// triangles would overlap without one matching). The same wall as a fan of quads agrees.
TEST(Sides, AThinWallOfAnyCornerCountIsOneTwoSidedSurface) {
    SceneFiles files;
    for (int n = 5; n <= 9; ++n) {
        for (int start : {0, 2, n - 1}) {
            SCOPED_TRACE("corners " + std::to_string(n) + ", tiles from " + std::to_string(start));
            files.write("wall.mgf", test::thin_wall_mgf(n, test::WallFaces::polygon, start));
            files.write("quads.mgf", test::thin_wall_mgf(n, test::WallFaces::quads));
            const MeshFile wall = load(files, "wall.mgf"), quads = load(files, "quads.mgf");
            EXPECT_EQ(wall.mesh.n_faces(), 2u + std::size_t(n - 2));  // the wall's triangles
            EXPECT_EQ(wall.repairs[RepairKind::sides_joined].count, 1u);
            EXPECT_EQ(wall.repairs[RepairKind::triangulated].count, 1u);
            EXPECT_EQ(quads.repairs[RepairKind::sides_joined].count, std::size_t(n - 1) / 2);
            EXPECT_NEAR(two_sided_wall_area(wall), two_sided_wall_area(quads), 1e-12);
        }
    }
}

// The polygons are compared once their repeated and collinear corners are out; a copy of a
// pentagon is dropped, and a third pentagon on its corners is an error, as for triangles.
TEST(Sides, PolygonsAreComparedAsTheyAreCut) {
    SceneFiles files;
    const std::string wall = test::thin_wall_mgf(5, test::WallFaces::polygon);
    const std::string paint = wall.substr(0, wall.find("m tile\n"));
    const std::size_t tile_line = std::size_t(std::count(paint.begin(), paint.end(), '\n')) + 2;
    // The tiles with a corner between w1 and w0 and w0 twice.
    files.write("collinear.mgf",
                paint + "v h =\n p 0.6545085 0.4755285 0\n" + "m tile\nf w2 w1 h w0 w0 w4 w3\n");
    const MeshFile collinear = load(files, "collinear.mgf");
    EXPECT_EQ(collinear.mesh.n_faces(), 2u + 3u);
    EXPECT_EQ(collinear.repairs[RepairKind::sides_joined].count, 1u);
    EXPECT_EQ(collinear.repairs[RepairKind::corners_removed].count, 1u);
    two_sided_wall_area(collinear);

    files.write("copy.mgf", wall + "m paint\nf w3 w4 w0 w1 w2\n");
    const MeshFile copy = load(files, "copy.mgf");
    EXPECT_EQ(copy.mesh.n_faces(), 2u + 3u);
    EXPECT_EQ(copy.repairs[RepairKind::duplicate_dropped].count, 1u);
    EXPECT_TRUE(contains(copy.repairs[RepairKind::sides_joined].first,
                         "copy.mgf:" + std::to_string(tile_line)));

    files.write("third.mgf", wall + "m lamp\nf w1 w2 w3 w4 w0\n");
    EXPECT_TRUE(contains(scene_error([&] { load(files, "third.mgf"); }),
                         "third.mgf:" + std::to_string(tile_line + 2) +
                             ": a third face on the same vertices as the faces on lines " +
                             std::to_string(tile_line - 2) + " and " + std::to_string(tile_line)));
}

TEST(Sides, TheRepairSummaryNamesTheNewKinds) {
    RepairReport r;
    r.add(RepairKind::sides_joined, "a.mgf:3");
    r.add(RepairKind::coincident_dropped, "a.mgf:4");
    r.add(RepairKind::coincident_dropped, "a.mgf:9");
    EXPECT_EQ(r.summary(),
              "1 face facing away from a coincident one joined as its back side (a.mgf:3), 2 "
              "coincident faces of another material dropped (the first kept) (first at a.mgf:4)");
    EXPECT_EQ(r.to_json()["sides_joined"]["count"], 1);
    EXPECT_EQ(r.to_json()["coincident_dropped"]["first"], "a.mgf:4");
}

}  // namespace
}  // namespace hmcr::sides_test
