// SPDX-License-Identifier: Apache-2.0
// load_scene: JSON scene files, bare OBJ files, bundled names, and their errors.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <numbers>
#include <optional>

#include "meshes/scene.h"
#include "tests/meshes/scene_files.h"

namespace hmcr {
namespace {

using test::contains;
using test::scene_error;
using test::SceneFiles;

constexpr const char* kLitTriangle =
    "mtllib tri.mtl\n"
    "usemtl light\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "f 1 2 3\n";
constexpr const char* kLightMtl = "newmtl light\nKd 0.5 0.5 0.5\nKe 1 1 1\n";

constexpr const char* kSceneJson = R"({
  "mesh": "tri.obj",
  "description": "one lit triangle",
  "views": [
    {"name": "front", "position": [0, 0, 3], "look_at": [0, 0, 0], "up": [0, 1, 0],
     "fov": 30, "width": 320, "height": 200},
    {"name": "side", "position": [3, 0, 0], "look_at": [0, 0, 0]}
  ],
  "solver": {"rays": 1000, "epsilon": 0.01}
}
)";

// Writes tri.obj + tri.mtl and the given JSON as scene.json; returns the JSON's path.
std::filesystem::path write_scene(const SceneFiles& files, const std::string& json) {
    files.write("tri.obj", kLitTriangle);
    files.write("tri.mtl", kLightMtl);
    return files.write("scene.json", json);
}

// Sets an environment variable for the lifetime of the object, then restores it.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : m_name(name) {
        if (const char* old = getenv(name)) m_old = old;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (m_old) {
            setenv(m_name, m_old->c_str(), 1);
        } else {
            unsetenv(m_name);
        }
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

TEST(SceneLoader, JsonSceneWithViews) {
    SceneFiles files;
    const Scene scene = load_scene(write_scene(files, kSceneJson).string());
    EXPECT_EQ(scene.name, "scene");
    EXPECT_EQ(scene.mesh_path, files.path() / "tri.obj");
    EXPECT_EQ(scene.mesh.n_faces(), 1u);
    ASSERT_EQ(scene.views.size(), 2u);
    const View& front = scene.views[0];
    EXPECT_EQ(front.name, "front");
    EXPECT_EQ(front.position, Eigen::Vector3d(0, 0, 3));
    EXPECT_EQ(front.fov_degrees, 30);
    EXPECT_EQ(front.width, 320);
    EXPECT_EQ(front.height, 200);
    EXPECT_EQ(scene.views[1].up, Eigen::Vector3d(0, 1, 0));  // defaults
    EXPECT_EQ(scene.views[1].width, 512);
    EXPECT_EQ(scene.solver_defaults.at("rays"), 1000);
}

TEST(SceneLoader, DefaultMaterialFromJson) {
    SceneFiles files;
    files.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto json = files.write(
        "scene.json", R"({"mesh": "plain.obj", "default_material": {"kd": [0.1, 0.2, 0.3],
                          "ke": [4, 5, 6]}})");
    Scene scene = load_scene(json.string());
    const OpenMesh::FaceHandle f(0);
    const FaceMaterial& m = FaceMaterials(scene.mesh)[f];
    EXPECT_EQ(m.reflectance, OpenMesh::Vec3d(0.1, 0.2, 0.3));
    EXPECT_EQ(m.emission, OpenMesh::Vec3d(4, 5, 6) * std::numbers::pi);
    ASSERT_EQ(scene.views.size(), 1u);  // no "views": the default view
}

TEST(SceneLoader, BadDefaultMaterial) {
    SceneFiles files;
    files.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto json = files.write(
        "scene.json", R"({"mesh": "plain.obj", "default_material": {"kd": [1.5, 0, 0]}})");
    EXPECT_TRUE(contains(scene_error([&] { load_scene(json.string()); }),
                         "scene.json: default_material: reflectance 1.5"));
}

TEST(SceneLoader, BareObjGetsADefaultViewFromOutside) {
    SceneFiles files;
    files.write("tri.mtl", kLightMtl);
    const auto obj = files.write("tri.obj", kLitTriangle);
    const Scene scene = load_scene(obj.string());
    EXPECT_EQ(scene.name, "tri");
    EXPECT_TRUE(scene.solver_defaults.empty());
    ASSERT_EQ(scene.views.size(), 1u);
    const View& v = scene.views[0];
    EXPECT_EQ(v.look_at, Eigen::Vector3d(0.5, 0.5, 0));
    EXPECT_GT(v.position.z(), 1.0);  // on the +z side, looking along -z
    EXPECT_EQ(v.position.head<2>(), v.look_at.head<2>());
}

TEST(SceneLoader, BadJsonGivesFileAndLine) {
    SceneFiles files;
    const auto json = write_scene(files, "{\n  \"mesh\": \"tri.obj\",\n  \"views\": [,]\n}\n");
    const std::string error = scene_error([&] { load_scene(json.string()); });
    EXPECT_TRUE(contains(error, "scene.json:3: "));
    EXPECT_TRUE(contains(error, "syntax error"));
    EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(SceneLoader, UnknownKey) {
    SceneFiles files;
    const auto json = write_scene(files, R"({"mesh": "tri.obj", "veiws": []})");
    EXPECT_TRUE(contains(scene_error([&] { load_scene(json.string()); }),
                         "scene.json: unknown key 'veiws'"));
}

// The scene loader keeps the solver object; the engine's settings table checks its keys.
TEST(SceneLoader, SolverMustBeAnObject) {
    SceneFiles files;
    const auto json = write_scene(files, R"({"mesh": "tri.obj", "solver": [1]})");
    EXPECT_TRUE(contains(scene_error([&] { load_scene(json.string()); }),
                         "scene.json: solver: must be a JSON object"));
}

TEST(SceneLoader, BadViews) {
    const auto view_error = [](const std::string& view) {
        SceneFiles files;
        const auto json = write_scene(files, R"({"mesh": "tri.obj", "views": [)" + view + "]}");
        return scene_error([&] { load_scene(json.string()); });
    };
    const std::string at = R"("name": "v", "position": [0, 0, 3], "look_at": [0, 0, 0])";
    EXPECT_TRUE(contains(view_error("{" + at + R"(, "fov": 180})"),
                         "views[0] ('v'): fov 180 is not in (0, 180)"));
    EXPECT_TRUE(contains(view_error("{" + at + R"(, "fov": 0})"), "fov 0 is not in"));
    EXPECT_TRUE(contains(view_error("{" + at + R"(, "width": 0})"), "width: must be a positive"));
    EXPECT_TRUE(contains(view_error("{" + at + R"(, "height": -5})"), "height: must be"));
    EXPECT_TRUE(contains(view_error("{" + at + R"(, "up": [0, 0, 0]})"), "up is the zero"));
    EXPECT_TRUE(contains(view_error("{" + at + R"(, "up": [0, 0, 2]})"), "up is parallel"));
    EXPECT_TRUE(
        contains(view_error(R"({"name": "v", "position": [1, 1, 1], "look_at": [1, 1, 1]})"),
                 "look_at equals position"));
    EXPECT_TRUE(contains(view_error(R"({"name": "v", "position": [1, 1], "look_at": [0, 0, 0]})"),
                         "position: must be an array of 3 finite numbers"));
}

TEST(SceneLoader, MeshErrorsNameTheMeshFile) {
    SceneFiles files;
    files.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    const auto json = files.write("scene.json", R"({"mesh": "tri.obj"})");
    // A degenerate face: dropped by the repairs (leaving no face), refused by a strict load.
    EXPECT_TRUE(contains(scene_error([&] { load_scene(json.string()); }), "tri.obj: no faces"));
    const auto strict = files.write("strict.json", R"({"mesh": "tri.obj", "strict": true})");
    EXPECT_TRUE(
        contains(scene_error([&] { load_scene(strict.string()); }), "tri.obj:4: degenerate face"));
}

TEST(SceneLoader, BundledSceneByName) {
    SceneFiles files;
    files.write("box/tri.obj", kLitTriangle);
    files.write("box/tri.mtl", kLightMtl);
    files.write("box/box.json", R"({"mesh": "tri.obj"})");
    files.write("empty/readme.txt", "not a scene: no empty.json");
    ScopedEnv env("HMCR_SCENES", files.path().string());
    EXPECT_EQ(scene_directory(), files.path());
    EXPECT_EQ(bundled_scene_names(), std::vector<std::string>{"box"});
    const Scene scene = load_scene("box");
    EXPECT_EQ(scene.name, "box");
    EXPECT_EQ(scene.source, files.path() / "box" / "box.json");
    EXPECT_EQ(scene.mesh.n_faces(), 1u);
}

// Without $HMCR_SCENES, the scenes are the data directory's (common/data_directory.h):
// $HMCR_DATA_DIR's, else, for a program in its build folder as this test is, the source tree's.
TEST(SceneLoader, BundledScenesAreTheDataDirectorys) {
    SceneFiles files;
    files.write("scenes/box/tri.obj", kLitTriangle);
    files.write("scenes/box/tri.mtl", kLightMtl);
    files.write("scenes/box/box.json", R"({"mesh": "tri.obj"})");
    ScopedEnv no_scenes("HMCR_SCENES", "");
    {
        ScopedEnv data("HMCR_DATA_DIR", files.path().string());
        EXPECT_EQ(scene_directory(), files.path() / "scenes");
        EXPECT_EQ(load_scene("box").source, files.path() / "scenes" / "box" / "box.json");
    }
    ScopedEnv no_data("HMCR_DATA_DIR", "");
    EXPECT_TRUE(std::filesystem::equivalent(scene_directory(), HMCR_SCENE_DIR));
}

TEST(SceneLoader, UnknownNameListsBundledScenes) {
    SceneFiles files;
    files.write("box/box.json", "{}");
    files.write("room/room.json", "{}");
    ScopedEnv env("HMCR_SCENES", files.path().string());
    EXPECT_EQ(scene_error([] { load_scene("nothing"); }),
              "nothing: no such file or bundled scene (bundled scenes: box, room)");
    EXPECT_TRUE(contains(scene_error([] { load_scene("missing.json"); }), "box, room"));
    // The extensions offered are the formats table's.
    const auto stl = files.write("mesh.stl", "solid\n");
    EXPECT_TRUE(contains(scene_error([&] { load_scene(stl.string()); }),
                         "mesh.stl: unknown extension '.stl': give a .json scene, a mesh (.obj, "
                         ".mgf, .ply, .gltf, .glb) or a bundled scene name (box, room)"));
}

TEST(SceneLoader, EveryBundledSceneLoads) {
    for (const std::string& name : bundled_scene_names()) {
        SCOPED_TRACE(name);
        // A generated scene (office) is tested on a small instance of its own (generated_test).
        if (test::read_file(scene_directory() / name / (name + ".json")).find("\"generator\"") !=
            std::string::npos) {
            continue;
        }
        const Scene scene = load_scene(name);
        EXPECT_GT(scene.mesh.n_faces(), 0u);
        EXPECT_FALSE(scene.views.empty());
    }
}

}  // namespace
}  // namespace hmcr
