// SPDX-License-Identifier: Apache-2.0
// The repairs (docs/usage.md#repairs): each kind on an OBJ that needs it (what was done, the
// report, its summary line), the same file refused with today's message under --strict, and what
// stays an error either way.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>

#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

constexpr const char* kRepairsMtl =
    "newmtl grey\nKd 0.5 0.5 0.5\n"
    "newmtl light\nKd 0 0 0\nKe 1 1 1\n"
    "newmtl white\nKd 1 1 1\n";

// Lines 1-3; the test's statements start on line 4. The light (a unit square at z = 5, facing
// down) is the last face of every file, so each test's own faces come first.
constexpr const char* kRepairsHeader = "mtllib scene.mtl\nusemtl grey\n# body\n";
constexpr const char* kLight = "usemtl light\nv 0 0 5\nv 0 1 5\nv 1 1 5\nv 1 0 5\nf -4 -3 -2 -1\n";

struct Loaded {
    MeshFile file;
    std::string error;
};

Loaded load(const std::string& body, bool strict = false) {
    SceneFiles files;
    files.write("scene.mtl", kRepairsMtl);
    const auto obj = files.write("scene.obj", kRepairsHeader + body + kLight);
    LoadOptions options;
    options.strict = strict;
    Loaded out;
    out.error = scene_error([&] { out.file = load_mesh(obj, options); });
    if (out.error == "<no InputError thrown>") out.error.clear();
    return out;
}

double face_area(const PatchMesh& mesh, OpenMesh::FaceHandle fh) {
    std::vector<Eigen::Vector3d> p;
    for (auto vh : mesh.fv_range(fh))
        p.emplace_back(mesh.point(vh)[0], mesh.point(vh)[1], mesh.point(vh)[2]);
    Eigen::Vector3d twice = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) twice += p[i].cross(p[(i + 1) % p.size()]);
    return 0.5 * twice.norm();
}

// Area of every face but the light (the last one).
double body_area(const PatchMesh& mesh) {
    double sum = 0;
    for (auto fh : mesh.faces()) {
        if (std::size_t(fh.idx()) + 1 < mesh.n_faces()) sum += face_area(mesh, fh);
    }
    return sum;
}

// An L-shaped hexagon (concave), area 3, on line 10.
constexpr const char* kHexagon =
    "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4 5 6\n";

TEST(Repairs, ConcavePolygonIsTriangulatedCoveringItsArea) {
    Loaded r = load(kHexagon);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.file.mesh.n_faces(), 4u + 1);
    EXPECT_NEAR(body_area(r.file.mesh), 3.0, 1e-12);
    const RepairTally& t = r.file.repairs[RepairKind::triangulated];
    EXPECT_EQ(t.count, 1u);
    EXPECT_TRUE(contains(t.first, "scene.obj:10"));
    EXPECT_EQ(r.file.repairs.summary(), "1 polygon triangulated (" + t.first + ")");
    auto line = source_line_prop(r.file.mesh);
    EXPECT_EQ(line[OpenMesh::FaceHandle(0)], 10);  // the pieces keep the polygon's line
}

TEST(Repairs, StrictRefusesTheSamePolygon) {
    EXPECT_TRUE(contains(load(kHexagon, true).error, "scene.obj:10: polygon with 6 vertices"));
}

// The quad's 4th corner is 0.1 off the plane of the others: split along the shorter diagonal
// (1-3, length 1.414, against 2-4, 1.418).
constexpr const char* kNonPlanarQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.1\nf 1 2 3 4\n";

TEST(Repairs, NonPlanarQuadIsSplitAlongTheShorterDiagonal) {
    const Loaded r = load(kNonPlanarQuad);
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.file.mesh.n_faces(), 2u + 1);
    EXPECT_EQ(r.file.repairs[RepairKind::quad_split].count, 1u);
    // Both triangles hold corners 1 and 3, (0,0,0) and (1,1,0): the ones with x = y.
    for (int f = 0; f < 2; ++f) {
        int on_diagonal = 0;
        for (auto vh : r.file.mesh.fv_range(OpenMesh::FaceHandle(f))) {
            const auto& p = r.file.mesh.point(vh);
            on_diagonal += (p[0] == p[1]) ? 1 : 0;
        }
        EXPECT_EQ(on_diagonal, 2) << "triangle " << f;
    }
    EXPECT_TRUE(contains(load(kNonPlanarQuad, true).error, "scene.obj:8: non-planar quad"));
}

TEST(Repairs, RepeatedCornerIsTakenOut) {
    const std::string quad = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 3\n";
    const Loaded r = load(quad);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.file.mesh.valence(OpenMesh::FaceHandle(0)), 3u);
    EXPECT_EQ(r.file.repairs[RepairKind::corners_removed].count, 1u);
    EXPECT_TRUE(contains(load(quad, true).error, "scene.obj:7: degenerate face"));
}

TEST(Repairs, FaceWithoutAreaIsDropped) {
    const std::string flat = "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nv 0 1 0\nf 1 2 -1\n";
    const Loaded r = load(flat);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.file.mesh.n_faces(), 1u + 1);
    EXPECT_EQ(r.file.repairs[RepairKind::degenerate_dropped].count, 1u);
    EXPECT_TRUE(contains(r.file.repairs.summary(), "1 degenerate face dropped ("));
    EXPECT_TRUE(contains(load(flat, true).error, "scene.obj:7: degenerate face"));
}

TEST(Repairs, ExactDuplicateIsDroppedAReversedOneIsTheBackAnotherMaterialLoses) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const Loaded same = load(tri + "f 2 3 1\n");
    ASSERT_TRUE(same.error.empty()) << same.error;
    EXPECT_EQ(same.file.mesh.n_faces(), 1u + 1);
    EXPECT_EQ(same.file.repairs[RepairKind::duplicate_dropped].count, 1u);
    EXPECT_TRUE(contains(same.file.repairs[RepairKind::duplicate_dropped].first, "scene.obj:8"));
    EXPECT_TRUE(contains(load(tri + "f 2 3 1\n", true).error, "scene.obj:8: duplicate face"));
    // Facing the other way: the back side, in the material of the face that faces that way.
    const Loaded back = load(tri + "usemtl white\nf 3 2 1\n");
    ASSERT_TRUE(back.error.empty()) << back.error;
    ASSERT_EQ(back.file.mesh.n_faces(), 1u + 1);
    EXPECT_TRUE(contains(back.file.repairs[RepairKind::sides_joined].first, "scene.obj:9"));
    const FaceMaterials m(back.file.mesh);
    const OpenMesh::FaceHandle f(0);
    EXPECT_EQ(m[f].reflectance[0], 0.5);                        // grey in front
    EXPECT_EQ(m.table()[m.back_index(f)].reflectance[0], 1.0);  // white behind
    // The same way in another material: the first face stays (strict: refused).
    const Loaded other = load(tri + "usemtl white\nf 1 2 3\n");
    ASSERT_TRUE(other.error.empty()) << other.error;
    ASSERT_EQ(other.file.mesh.n_faces(), 1u + 1);
    EXPECT_TRUE(contains(other.file.repairs[RepairKind::coincident_dropped].first, "scene.obj:9"));
    EXPECT_EQ(FaceMaterials(other.file.mesh)[f].reflectance[0], 0.5);
    EXPECT_TRUE(contains(load(tri + "usemtl light\nf 1 2 3\n", true).error,
                         "scene.obj:9: duplicate face: same vertices as the face on line 7, "
                         "with another material"));
}

TEST(Repairs, EveryLaterCopyIsDroppedTheFirstKeptInItsPlace) {
    // Faces on lines 8-12: A, B, A from another corner, B from another corner, A again.
    const Loaded r = load(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "f 1 2 3\nf 1 3 4\nf 2 3 1\nf 4 1 3\nf 1 2 3\n");
    ASSERT_TRUE(r.error.empty()) << r.error;
    ASSERT_EQ(r.file.mesh.n_faces(), 2u + 1);  // and the light
    EXPECT_EQ(r.file.repairs[RepairKind::duplicate_dropped].count, 3u);
    EXPECT_TRUE(contains(r.file.repairs[RepairKind::duplicate_dropped].first, "scene.obj:10"));
    // The kept faces are A then B, in file order: B's corners are vertices 0, 2 and 3.
    std::vector<int> b;
    for (auto v : r.file.mesh.fv_range(OpenMesh::FaceHandle(1))) b.push_back(v.idx());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(b, (std::vector<int>{0, 2, 3}));
}

TEST(Repairs, ReflectanceOneIsAcceptedWithAWarningAboveOneIsNot) {
    const std::string tri = "usemtl white\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const Loaded r = load(tri);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.file.repairs[RepairKind::reflectance_one].count, 1u);
    EXPECT_TRUE(contains(r.file.repairs[RepairKind::reflectance_one].first, "scene.mtl:7"));
    ASSERT_EQ(r.file.warnings.size(), 1u);
    EXPECT_TRUE(
        contains(r.file.warnings[0], "scene.mtl:7: reflectance 1 of material 'white' accepted"));
    EXPECT_TRUE(contains(load(tri, true).error,
                         "scene.mtl:7: reflectance 1 of material 'white' is not below 1"));
    SceneFiles files;
    files.write("scene.mtl", "newmtl light\nKd 1.01 0 0\nKe 1 1 1\n");
    const auto obj = files.write("scene.obj",
                                 "mtllib scene.mtl\nusemtl light\nv 0 0 0\nv 1 0 0\n"
                                 "v 0 1 0\nf 1 2 3\n");
    EXPECT_TRUE(contains(scene_error([&] { load_mesh(obj); }), "scene.mtl:2: reflectance 1.01"));
}

TEST(Repairs, SelfIntersectingPolygonStaysAnError) {
    const std::string bow = "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nv 0.5 2 0\nf 1 2 3 4 5\n";
    EXPECT_TRUE(contains(load(bow).error, "scene.obj:9: self-intersecting polygon"));
    const std::string bow_quad = "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n";
    EXPECT_TRUE(contains(load(bow_quad).error, "scene.obj:8: self-intersecting"));
}

TEST(Repairs, SummaryAndJsonCountEveryKind) {
    // The hexagon, a pentagon (line 16) and a triangle without area (line 20).
    const std::string pentagon =
        "v 0 0 3\nv 1 0 3\nv 1 1 3\nv 0.5 1.5 3\nv 0 1 3\nf -5 -4 -3 -2 -1\n";
    const Loaded r =
        load(std::string(kHexagon) + pentagon + "v 0 0 1\nv 1 0 1\nv 2 0 1\nf -3 -2 -1\n");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_EQ(r.file.repairs.total(), 3u);  // triangulated twice, one degenerate face dropped
    const nlohmann::json j = r.file.repairs.to_json();
    EXPECT_EQ(j["count"], 3);
    EXPECT_EQ(j["triangulated"]["count"], 2);
    EXPECT_TRUE(contains(j["triangulated"]["first"].get<std::string>(), "scene.obj:10"));
    EXPECT_EQ(j["degenerate_dropped"]["count"], 1);
    EXPECT_FALSE(j.contains("quads_split"));
    EXPECT_TRUE(contains(r.file.repairs.summary(), "2 polygons triangulated (first at "));
}

TEST(Repairs, AGoodSceneNeedsNone) {
    const Loaded r = load("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_TRUE(r.file.repairs.empty());
    EXPECT_EQ(r.file.repairs.summary(), "");
}

}  // namespace
}  // namespace hmcr
