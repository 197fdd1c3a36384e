// SPDX-License-Identifier: Apache-2.0
// load_scene: a bundled scene name, a JSON scene file or a bare mesh file -> Scene.
//
// JSON scene file (keys other than these are an error, to catch typos):
//   {
//     "mesh": "cornell.obj",              required; relative to the JSON file; a format of
//                                         kMeshFormats (.obj, .mgf, .ply, .gltf, .glb)
//     "description": "...",               optional string
//     "views": [                          optional; each view:
//       {"name": "camera",                  required, unique; it names files (views/camera.pfm),
//                                           so common/file_names.h's characters, 1-64 bytes
//        "position": [x, y, z],             required, metres
//        "look_at": [x, y, z],              required, != position
//        "up": [x, y, z],                   optional, default [0, 1, 0]; not along the view
//        "fov": 39.31,                      optional, vertical, degrees in (0, 180), default 40
//        "width": 512, "height": 512}       optional, pixels > 0, default 512
//     ],
//     "solver": {...},                    optional object, copied to Scene::solver_defaults
//     "default_material": {"kd": [r, g, b], "ke": [r, g, b]}
//                                         optional; used by faces without a material;
//                                         kd defaults to 0.5 grey, ke to 0
//     "strict": true,                     optional; refuse what the repairs would fix
//     "mgf_segments": 24,                 optional; segments per circle of MGF curved surfaces
//     "sides": 1,                         optional; every material's sides; --sides wins
//     "material_sides": {"leaf": 2},      optional; sides of materials by name, over "sides"
//     "generator": "generate.py"          optional; the script beside the file that writes a
//                                         mesh too large for git (named when it is missing)
//   }
// A scene without views (a bare .obj, or a JSON file without "views") gets one view named
// "default", inside its room where it has one (meshes/scene_bounds.h).
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string_view>

#include "common/data_directory.h"
#include "common/file_names.h"
#include "common/text_file.h"
#include "meshes/gltf_reader.h"
#include "meshes/material_sides.h"
#include "meshes/mgf_reader.h"
#include "meshes/obj_reader.h"
#include "meshes/ply_reader.h"
#include "meshes/repairs.h"
#include "meshes/scene.h"
#include "meshes/scene_bounds.h"
#include "meshes/validation.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& message) {
    throw InputError(where, message);
}

std::string bundled_list() {
    const std::vector<std::string> names = bundled_scene_names();
    if (names.empty()) return fmt::format("none found in {}", scene_directory().string());
    return fmt::format("{}", fmt::join(names, ", "));
}

// The definition of bundled_scene_names(), for one name.
bool is_bundled(const std::string& name) {
    std::error_code ec;
    return !name.empty() && name.find('/') == std::string::npos &&
           fs::is_regular_file(scene_directory() / name / (name + ".json"), ec);
}

void check_keys(const json& object, const std::set<std::string>& known, const std::string& where) {
    if (!object.is_object()) fail(where, "must be a JSON object");
    for (const auto& [key, value] : object.items()) {
        if (known.count(key) == 0) {
            fail(where,
                 fmt::format("unknown key {} (known: {})", quote(key), fmt::join(known, ", ")));
        }
    }
}

Eigen::Vector3d vector3(const json& value, const std::string& where) {
    const bool ok = value.is_array() && value.size() == 3 &&
                    std::all_of(value.begin(), value.end(), [](const json& x) {
                        return x.is_number() && std::isfinite(x.get<double>());
                    });
    if (!ok) fail(where, "must be an array of 3 finite numbers");
    return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

double number(const json& value, const std::string& where) {
    if (!value.is_number()) fail(where, "must be a number");
    return value.get<double>();
}

int pixels(const json& value, const std::string& where) {
    if (!value.is_number_integer() || value.get<long long>() <= 0 ||
        value.get<long long>() > 1 << 16) {
        fail(where, "must be a positive integer of at most 65536");
    }
    return value.get<int>();
}

void check_view(const View& v, const std::string& where) {
    if (!(v.fov_degrees > 0 && v.fov_degrees < 180)) {
        fail(where, fmt::format("fov {} is not in (0, 180) degrees", v.fov_degrees));
    }
    const Eigen::Vector3d direction = v.look_at - v.position;
    if (direction.norm() == 0) fail(where, "look_at equals position: no view direction");
    if (v.up.norm() == 0) fail(where, "up is the zero vector");
    if (direction.normalized().cross(v.up.normalized()).norm() < 1e-9) {
        fail(where, "up is parallel to the view direction");
    }
}

View parse_view(const json& j, const std::string& file, std::size_t index) {
    std::string where = fmt::format("{}: views[{}]", file, index);
    check_keys(j, {"name", "position", "look_at", "up", "fov", "width", "height"}, where);
    if (!j.contains("name") || !j["name"].is_string()) fail(where, "needs a \"name\" string");
    View v;
    v.name = j["name"].get<std::string>();
    if (const auto why = name_problem(v.name)) {
        fail(where, fmt::format("name {} cannot name a file: {}", quote(v.name), *why));
    }
    where += fmt::format(" ('{}')", v.name);
    for (const char* key : {"position", "look_at"}) {
        if (!j.contains(key)) fail(where, fmt::format("needs \"{}\"", key));
    }
    v.position = vector3(j["position"], where + ": position");
    v.look_at = vector3(j["look_at"], where + ": look_at");
    if (j.contains("up")) v.up = vector3(j["up"], where + ": up");
    if (j.contains("fov")) v.fov_degrees = number(j["fov"], where + ": fov");
    if (j.contains("width")) v.width = pixels(j["width"], where + ": width");
    if (j.contains("height")) v.height = pixels(j["height"], where + ": height");
    check_view(v, where);
    return v;
}

std::vector<View> parse_views(const json& views, const std::string& file) {
    if (!views.is_array()) fail(file, "\"views\" must be an array");
    std::vector<View> out;
    std::set<std::string> names;
    for (std::size_t i = 0; i < views.size(); ++i) {
        out.push_back(parse_view(views[i], file, i));
        if (!names.insert(out.back().name).second) {
            fail(file, fmt::format("two views are named '{}'", out.back().name));
        }
    }
    return out;
}

Material parse_default_material(const json& j, const std::string& file, bool strict) {
    const std::string where = file + ": default_material";
    check_keys(j, {"kd", "ke"}, where);
    Material m;
    m.name = "default";
    m.kd = Eigen::Vector3d::Constant(0.5);
    if (j.contains("kd")) m.kd = vector3(j["kd"], where + ": kd");
    if (j.contains("ke")) m.ke = vector3(j["ke"], where + ": ke");
    if (auto error = check_reflectance(m, !strict)) fail(where, *error);
    if (auto error = check_emission(m)) fail(where, *error);
    return m;
}

// The mesh formats, by extension: the one place a format is added.
struct MeshFormat {
    std::string_view extension;
    PolygonSoup (*read)(const fs::path& path, const LoadOptions& options);
};

constexpr MeshFormat kMeshFormats[] = {
    {".obj", [](const fs::path& path, const LoadOptions&) { return read_obj(path); }},
    {".mgf",
     [](const fs::path& path, const LoadOptions& options) {
         MgfOptions mgf;
         mgf.curve_segments = options.curve_segments.value_or(kDefaultCurveSegments);
         return read_mgf(path, mgf);
     }},
    {".ply", [](const fs::path& path, const LoadOptions&) { return read_ply(path); }},
    {".gltf", [](const fs::path& path, const LoadOptions&) { return read_gltf(path); }},
    {".glb", [](const fs::path& path, const LoadOptions&) { return read_gltf(path); }},
};

const MeshFormat* find_mesh_format(const fs::path& path) {
    const std::string extension = path.extension().string();
    for (const MeshFormat& format : kMeshFormats) {
        if (format.extension == extension) return &format;
    }
    return nullptr;
}

// ".obj, .mgf, ...": the formats a message offers.
std::string mesh_extensions() {
    std::vector<std::string_view> extensions;
    for (const MeshFormat& format : kMeshFormats) extensions.push_back(format.extension);
    return fmt::format("{}", fmt::join(extensions, ", "));
}

std::string formats_read() { return fmt::format("hmcr reads meshes of {}", mesh_extensions()); }

void check_mesh_extension(const fs::path& mesh, const std::string& where) {
    if (find_mesh_format(mesh) == nullptr) {
        fail(where, fmt::format("mesh {}: {}", quote(mesh.string()), formats_read()));
    }
}

void take_mesh(Scene& scene, const fs::path& path, const LoadOptions& options) {
    MeshReport file = load_mesh(path, options, scene.mesh);
    scene.inputs.insert(scene.inputs.end(), file.files.begin(), file.files.end());
    scene.warnings = std::move(file.warnings);
    scene.repairs = std::move(file.repairs);
    scene.strict = options.strict;
    scene.curve_segments = options.curve_segments.value_or(kDefaultCurveSegments);
}

// A scene file's "strict", "mgf_segments" and sides; the command line's segment count wins.
void apply_load_keys(const json& j, const std::string& file, LoadOptions& options) {
    apply_sides_keys(j, file, options);  // meshes/material_sides.h
    if (j.contains("strict")) {
        if (!j["strict"].is_boolean()) fail(file + ": strict", "must be true or false");
        options.strict = options.strict || j["strict"].get<bool>();
    }
    if (j.contains("mgf_segments") && !options.curve_segments) {
        const json& n = j["mgf_segments"];
        if (!n.is_number_integer() || n.get<long long>() < kMinCurveSegments ||
            n.get<long long>() > kMaxCurveSegments) {
            fail(file + ": mgf_segments", fmt::format("must be an integer in [{}, {}]",
                                                      kMinCurveSegments, kMaxCurveSegments));
        }
        options.curve_segments = n.get<int>();
    }
}

Scene load_json_scene(const fs::path& path, const std::string& name, LoadOptions options) {
    const std::string file = path.string();
    const json j = read_json_file(path);
    check_keys(j,
               {"mesh", "description", "views", "solver", "default_material", "strict",
                "mgf_segments", "sides", "material_sides", "generator"},
               file);
    if (!j.contains("mesh") || !j["mesh"].is_string()) fail(file, "needs a \"mesh\" string");
    if (j.contains("description") && !j["description"].is_string()) {
        fail(file, "\"description\" must be a string");
    }
    Scene scene;
    scene.name = name;
    scene.source = path;
    scene.inputs.push_back(path);
    // Normal, as the readers name their files: `scenes/../x.mgf` is `x.mgf` in every message.
    scene.mesh_path = (path.parent_path() / j["mesh"].get<std::string>()).lexically_normal();
    check_mesh_extension(scene.mesh_path, file);
    if (j.contains("generator")) {
        if (!j["generator"].is_string()) fail(file, "\"generator\" must be a string");
        std::error_code ec;
        if (!fs::exists(scene.mesh_path, ec)) {
            fail(scene.mesh_path.string(),
                 fmt::format("no such file: this scene's mesh is generated on demand, by "
                             "`python3 {}` (or `make scenes`)",
                             (path.parent_path() / j["generator"].get<std::string>()).string()));
        }
    }
    if (j.contains("views")) scene.views = parse_views(j["views"], file);
    if (j.contains("solver")) {
        // Checked, key by key, by the engine's settings table where a command applies them.
        if (!j["solver"].is_object()) fail(file + ": solver", "must be a JSON object");
        scene.solver_defaults = j["solver"];
    }
    apply_load_keys(j, file, options);
    options.default_material.reset();
    if (j.contains("default_material")) {
        options.default_material =
            parse_default_material(j["default_material"], file, options.strict);
    }
    take_mesh(scene, scene.mesh_path, options);
    if (scene.views.empty()) {
        scene.views.push_back(default_view(scene.mesh));
        scene.default_views = true;
    }
    return scene;
}

Scene load_mesh_scene(const fs::path& path, LoadOptions options) {
    check_mesh_extension(path, path.string());
    Scene scene;
    scene.name = path.stem().string();
    scene.source = path;
    scene.mesh_path = path.lexically_normal();
    options.default_material.reset();
    take_mesh(scene, scene.mesh_path, options);
    scene.views.push_back(default_view(scene.mesh));
    scene.default_views = true;
    return scene;
}

Scene load_file(const fs::path& path, const LoadOptions& options) {
    const std::string extension = path.extension().string();
    if (extension == ".json") return load_json_scene(path, path.stem().string(), options);
    if (find_mesh_format(path) != nullptr) return load_mesh_scene(path, options);
    fail(path.string(), fmt::format("unknown extension {}: give a .json scene, a mesh ({}) or a "
                                    "bundled scene name ({})",
                                    quote(extension), mesh_extensions(), bundled_list()));
}

// Tells the reader's warnings, repairs the soup unless strict (telling the repairs' warnings),
// and builds the patch mesh.
MeshReport load_soup(PolygonSoup soup, const LoadOptions& options, PatchMesh& mesh) {
    const auto tell = [&](std::size_t from) {
        if (!options.warn) return;
        for (std::size_t w = from; w < soup.warnings.size(); ++w) options.warn(soup.warnings[w]);
    };
    check_positions(soup);  // before the warnings: a refusal is one line
    tell(0);
    assign_sides(soup, options);
    RepairReport repairs;
    const Welding welding = weld(soup.positions);  // once: the repairs keep the positions
    if (options.strict) {
        repairs = join_opposite_faces(soup, welding);
    } else {
        const std::size_t told = soup.warnings.size();
        repairs = repair_soup(soup, welding);
        tell(told);
    }
    LoadOptions effective = options;
    // Measuring geometry: faces without a material get a neutral one.
    if (options.use == SceneUse::geometry && !options.default_material) {
        effective.default_material = Material{"default", Eigen::Vector3d::Constant(0.5), {0, 0, 0}};
    }
    build_patch_mesh(soup, welding, effective, mesh);
    return {soup.files, std::move(soup.warnings), std::move(repairs)};
}

}  // namespace

std::vector<View> read_views(const json& views, const std::string& where) {
    return parse_views(views, where);
}

Scene load_soup_scene(const std::string& name, PolygonSoup soup, const LoadOptions& options) {
    Scene scene;
    scene.name = name;
    scene.strict = options.strict;
    MeshReport report = load_soup(std::move(soup), options, scene.mesh);
    scene.warnings = std::move(report.warnings);
    scene.repairs = std::move(report.repairs);
    scene.views.push_back(default_view(scene.mesh));
    scene.default_views = true;
    return scene;
}

const View& find_view(const Scene& scene, const std::string& name) {
    if (scene.views.empty()) throw InputError(scene.name + " has no views");
    if (name.empty()) return scene.views.front();
    std::string names;
    for (const View& v : scene.views) {
        if (v.name == name) return v;
        names += (names.empty() ? "" : ", ") + v.name;
    }
    throw InputError(
        fmt::format("scene {} has no view {} (views: {})", scene.name, quote(name), names));
}

MeshReport load_mesh(const fs::path& path, const LoadOptions& options, PatchMesh& mesh) {
    const MeshFormat* format = find_mesh_format(path);
    if (format == nullptr) throw InputError(path.string(), formats_read());
    return load_soup(format->read(path, options), options, mesh);
}

MeshFile load_mesh(const fs::path& path, const LoadOptions& options) {
    MeshFile file;
    static_cast<MeshReport&>(file) = load_mesh(path, options, file.mesh);
    return file;
}

PatchMesh load_obj(const fs::path& obj, const LoadOptions& options) {
    PatchMesh mesh;
    load_soup(read_obj(obj), options, mesh);
    return mesh;
}

fs::path scene_directory() {
    const char* env = std::getenv("HMCR_SCENES");
    if (env != nullptr && *env != '\0') return env;
    return data_directory() / "scenes";
}

std::vector<std::string> bundled_scene_names() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(scene_directory(), ec)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory(ec) && fs::is_regular_file(entry.path() / (name + ".json"), ec)) {
            names.push_back(name);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

Scene load_scene(const std::string& name_or_path, SceneUse use, const WarningFn& warn) {
    LoadOptions options;
    options.use = use;
    options.warn = warn;
    return load_scene(name_or_path, options);
}

Scene load_scene(const std::string& name_or_path, const LoadOptions& options) {
    const fs::path path(name_or_path);
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) return load_file(path, options);
    if (is_bundled(name_or_path)) {
        return load_json_scene(scene_directory() / name_or_path / (name_or_path + ".json"),
                               name_or_path, options);
    }
    fail(name_or_path,
         fmt::format("no such file or bundled scene (bundled scenes: {})", bundled_list()));
}

}  // namespace hmcr
