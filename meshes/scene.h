// SPDX-License-Identifier: Apache-2.0
// A scene: the patch mesh plus what its optional JSON scene file says (views, solver defaults).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/error.h"
#include "meshes/patch_mesh.h"
#include "meshes/repair_report.h"
#include "meshes/view.h"

namespace hmcr {

struct Material {
    std::string name;
    Eigen::Vector3d kd{0, 0, 0};  // diffuse reflectance rho, each channel in [0, 1]
    Eigen::Vector3d ke{0, 0, 0};  // emitted radiance, W sr^-1 m^-2; E = pi * ke
    // Specular reflectance (docs/design.md §1.2), kd + ks in [0, 1] per channel: an ideal mirror
    // at roughness 0, else the glossy lobe of MGF's `rs` with roughness its RMS facet slope.
    // The path tracer reflects it; the radiosity engine absorbs it.
    Eigen::Vector3d ks{0, 0, 0};
    double roughness = 0;  // in [0, 1]
};

// What the scene is loaded for. Solving needs an emitter and a material on every face;
// measuring the geometry (`hmcr info`) needs neither, so there a scene without light loads and
// faces without a material get a neutral grey (the other checks all apply).
enum class SceneUse { solve, geometry };

// Told each warning of the readers ("file:line: what") as soon as it is found, so that it is
// seen even when the load then fails (a typo that turned a light off, then "no emitter").
using WarningFn = std::function<void(const std::string&)>;

// Segments per full circle of MGF's curved surfaces (sph, cyl, cone, ring, torus) when neither
// the command line nor the scene file sets it (docs/usage.md#mgf).
inline constexpr int kDefaultCurveSegments = 24;
inline constexpr int kMinCurveSegments = 4;
inline constexpr int kMaxCurveSegments = 256;

// The sides of a material whose file does not say (an OBJ's: Blender and Cycles treat a
// diffuse face as two-sided, docs/decisions.md) when neither the command line nor the scene file
// sets them (docs/usage.md#sides).
inline constexpr int kDefaultSides = 2;

// A scene file's sides for materials by name ("material_sides"), and where it says so.
struct MaterialSides {
    std::map<std::string, int> by_name;  // 1 or 2
    std::string where;                   // "scene.json: material_sides"
};

struct LoadOptions {
    std::optional<Material> default_material;  // used by faces without a material
    SceneUse use = SceneUse::solve;
    WarningFn warn;                     // optional
    bool strict = false;                // refuse what the repairs would fix (docs/usage.md#repairs)
    std::optional<int> curve_segments;  // MGF tessellation; a scene file's value, else the default
    // Every material's sides (1 or 2): the command line's, else a scene file's; unset: each
    // material's own (MGF's `sides`), else kDefaultSides. material_sides is over both.
    std::optional<int> sides;
    MaterialSides material_sides;
};

// What loading a mesh file told: every file read for it (the mesh and its material libraries),
// the warnings of the readers, one line each, and the repairs.
struct MeshReport {
    std::vector<std::filesystem::path> files;
    std::vector<std::string> warnings;
    RepairReport repairs;  // empty for a strict load
};

// A mesh file as loaded: the validated patch mesh and its report.
struct MeshFile : MeshReport {
    PatchMesh mesh;
};

struct Scene {
    std::string name;                           // bundled name, or the file's stem
    std::filesystem::path source;               // the file given by the user (JSON or mesh)
    std::filesystem::path mesh_path;            // the mesh file actually read
    std::vector<std::filesystem::path> inputs;  // every file read: no output may replace one
    std::vector<std::string> warnings;          // the loaders' warnings ("file:line: what")
    RepairReport repairs;                       // what the load repaired (docs/usage.md#repairs)
    bool strict = false;  // loaded with --strict or a scene file's "strict": true
    int curve_segments = kDefaultCurveSegments;  // MGF tessellation used
    PatchMesh mesh;                              // validated, with the hmcr:* face properties
    std::vector<View> views;
    bool default_views = false;  // views is the "default" view alone: the scene has none of its own
    nlohmann::json solver_defaults = nlohmann::json::object();  // "solver" object of the file
};

// Reads a mesh file (by extension: .obj with its MTL files, .mgf with its includes), repairs it
// unless options.strict, validates it (docs/design.md §1) and returns the patch mesh. Throws
// InputError on any problem.
MeshFile load_mesh(const std::filesystem::path& path, const LoadOptions& options = {});
// The same built into `mesh` (empty): OpenMesh's meshes have no move, and a copy of a large
// mesh costs its whole size again.
MeshReport load_mesh(const std::filesystem::path& path, const LoadOptions& options,
                     PatchMesh& mesh);
// An OBJ file whatever its extension, and its mesh alone.
PatchMesh load_obj(const std::filesystem::path& obj, const LoadOptions& options = {});

// Accepts a bundled scene name ("cornell"), a JSON scene file, or a mesh file (.obj, .mgf).
Scene load_scene(const std::string& name_or_path, SceneUse use = SceneUse::solve,
                 const WarningFn& warn = {});
// The same with every load option (default_material is ignored: a scene file sets it).
Scene load_scene(const std::string& name_or_path, const LoadOptions& options);

// Views given as a scene file's "views" array, checked as a scene file's are: throws InputError
// "WHERE: views[i] ('name'): why".
std::vector<View> read_views(const nlohmann::json& views, const std::string& where);

// The view called name (the first view for ""); throws InputError listing the views.
const View& find_view(const Scene& scene, const std::string& name);

// Names of the bundled scenes (folders of the scene directory holding NAME/NAME.json).
std::vector<std::string> bundled_scene_names();

// Where bundled scenes live: $HMCR_SCENES if set, else the data directory's scenes/
// (common/data_directory.h).
std::filesystem::path scene_directory();

}  // namespace hmcr
