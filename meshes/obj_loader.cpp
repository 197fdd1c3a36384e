// load_obj: OBJ + MTL -> validated PatchMesh.
//
// Steps: read the files ourselves (so an unreadable MTL is an error, not a warning), pre-scan
// them for line numbers and lexical errors (obj_lines.h), let tinyobjloader parse them in double
// precision without triangulation, weld equal positions, validate every face (validation.h) and
// build the OpenMesh mesh with the hmcr:* face properties.
#ifndef TINYOBJLOADER_USE_DOUBLE
#define TINYOBJLOADER_USE_DOUBLE  // the tinyobjloader_double target defines it too
#endif
#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <OpenMesh/Core/System/omstream.hh>
#include <array>
#include <cmath>
#include <algorithm>
#include <map>
#include <set>
#include <numbers>

#include "common/text_file.h"
#include "meshes/obj_lines.h"
#include "meshes/scene.h"
#include "meshes/validation.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// One face as tinyobjloader returned it, with our welded vertex ids and its statement.
struct LoadedFace {
    std::vector<int> ids;                  // welded vertex ids, in file order
    std::vector<Eigen::Vector3d> corners;  // their positions
    int material_id = -1;                  // tinyobjloader's material index, -1 = none
    const FaceStatement* statement = nullptr;
};

struct LoadedObj {
    std::vector<Eigen::Vector3d> points;  // welded positions
    std::vector<LoadedFace> faces;
    std::vector<tinyobj::material_t> materials;
};

[[noreturn]] void fail(const std::string& where, const std::string& message) {
    throw InputError(where, message);
}

// Reads the first readable file of every mtllib statement (tinyobjloader's rule) and returns
// their concatenated text for tinyobjloader; records where each material was defined.
// The text of a material library named by an mtllib statement; its problems are reported at
// the statement.
std::string read_library(const fs::path& path, const fs::path& obj, int line) {
    try {
        return read_text_file(path);
    } catch (const InputError& e) {
        fail(at(obj, line), fmt::format("material library: {}", e.what()));
    }
}

// Reads the first existing file of every mtllib statement (tinyobjloader's rule) and returns
// their concatenated text for tinyobjloader; records where each material was defined.
std::string read_materials(const fs::path& obj, const ObjLines& lines, MtlLines& mtl_lines) {
    std::string text;
    std::set<std::string> loaded;
    for (const MtllibStatement& statement : lines.mtllibs) {
        const auto name = std::find_if(statement.files.begin(), statement.files.end(),
                                       [&](const std::string& n) {
                                           std::error_code ec;
                                           return loaded.count(n) != 0 ||
                                                  fs::exists(obj.parent_path() / n, ec);
                                       });
        if (name == statement.files.end()) {
            fail(at(obj, statement.line),
                 fmt::format("cannot read material library {}: no such file",
                             quote(statement.files.front())));
        }
        if (!loaded.insert(*name).second) continue;
        const fs::path path = obj.parent_path() / *name;
        const std::string mtl = read_library(path, obj, statement.line);
        scan_mtl(mtl, path.string(), mtl_lines);
        text += mtl + "\n";
    }
    return text;
}

tinyobj::ObjReader parse_with_tinyobj(const std::string& obj_text, const std::string& mtl_text,
                                      const std::string& path) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // quads are patches; we validate them, not split them
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(obj_text, mtl_text, config)) {
        const std::string& error = reader.Error();
        fail(path, "tinyobjloader: " + error.substr(0, error.find('\n')));
    }
    return reader;
}

// Welds exactly equal positions: faces that share a corner position share a vertex id, which
// later becomes one OpenMesh vertex, so neighbouring patches are adjacent in the mesh.
std::vector<int> weld(const std::vector<tinyobj::real_t>& xyz, const ObjLines& lines,
                      const std::string& path, std::vector<Eigen::Vector3d>& points) {
    std::map<std::array<double, 3>, int> index;
    std::vector<int> welded(xyz.size() / 3);
    for (std::size_t k = 0; k < welded.size(); ++k) {
        const std::array<double, 3> p{xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]};
        for (double c : p) {
            if (!std::isfinite(c)) {
                fail(at(path, lines.vertex_lines[k]),
                     fmt::format("coordinate {} is not a finite number", c));
            }
        }
        auto [it, inserted] = index.try_emplace(p, static_cast<int>(points.size()));
        if (inserted) points.emplace_back(p[0], p[1], p[2]);
        welded[k] = it->second;
    }
    return welded;
}

// Flattens tinyobjloader's shapes into faces in file order and pairs the k-th face with the
// k-th `f` statement of the pre-scan.
std::vector<LoadedFace> collect_faces(const tinyobj::ObjReader& reader, const ObjLines& lines,
                                      const std::vector<int>& welded,
                                      const std::vector<Eigen::Vector3d>& points,
                                      const std::string& path) {
    std::vector<LoadedFace> faces;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            LoadedFace face;
            face.material_id = shape.mesh.material_ids[f];
            for (unsigned i = 0; i < shape.mesh.num_face_vertices[f]; ++i, ++offset) {
                const int v = shape.mesh.indices.at(offset).vertex_index;
                if (v < 0 || static_cast<std::size_t>(v) >= welded.size()) {
                    fail(path, "internal error: tinyobjloader returned a bad vertex index");
                }
                face.ids.push_back(welded[v]);
                face.corners.push_back(points[welded[v]]);
            }
            faces.push_back(std::move(face));
        }
    }
    if (faces.size() != lines.faces.size()) {
        fail(path, fmt::format("internal error: tinyobjloader read {} faces, hmcr counted {}",
                               faces.size(), lines.faces.size()));
    }
    for (std::size_t k = 0; k < faces.size(); ++k) faces[k].statement = &lines.faces[k];
    return faces;
}

LoadedObj load_geometry(const tinyobj::ObjReader& reader, const ObjLines& lines,
                        const std::string& path) {
    const std::vector<tinyobj::real_t>& xyz = reader.GetAttrib().vertices;
    if (xyz.size() != 3 * lines.vertex_lines.size()) {
        fail(path, fmt::format("internal error: tinyobjloader read {} vertices, hmcr counted {}",
                               xyz.size() / 3, lines.vertex_lines.size()));
    }
    LoadedObj obj;
    const std::vector<int> welded = weld(xyz, lines, path, obj.points);
    obj.faces = collect_faces(reader, lines, welded, obj.points, path);
    obj.materials = reader.GetMaterials();
    return obj;
}

Material to_material(const tinyobj::material_t& m) {
    Material out;
    out.name = m.name;
    out.kd = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    out.ke = {m.emission[0], m.emission[1], m.emission[2]};
    return out;
}

// Where a Kd/Ke problem of `name` is reported: its statement in the MTL, else the OBJ.
std::string material_where(const MtlLines& mtl_lines, const std::string& name, bool kd,
                           const std::string& fallback) {
    auto it = mtl_lines.find(name);
    if (it == mtl_lines.end()) return fallback;
    const MtlMaterialLines& m = it->second;
    const int line = kd ? m.kd_line : m.ke_line;
    return at(m.file, line != 0 ? line : m.newmtl_line);
}

// The material of a face: its own (validated), else the default, else an error.
Material face_material(const LoadedObj& obj, const LoadedFace& face, const MtlLines& mtl_lines,
                       const LoadOptions& options, const std::string& path) {
    const std::string where = at(path, face.statement->line);
    const auto id = face.material_id;
    if (id >= 0 && static_cast<std::size_t>(id) < obj.materials.size()) {
        Material m = to_material(obj.materials[id]);
        if (auto error = check_reflectance(m)) {
            fail(material_where(mtl_lines, m.name, true, where), *error);
        }
        if (auto error = check_emission(m)) {
            fail(material_where(mtl_lines, m.name, false, where), *error);
        }
        return m;
    }
    if (options.default_material) return *options.default_material;
    const std::string& name = face.statement->usemtl;
    if (name.empty()) fail(where, "face has no material (no usemtl before it)");
    fail(where, fmt::format("face uses material '{}', which no loaded MTL file defines", name));
}

void check_default_material(const LoadOptions& options, const std::string& path) {
    if (!options.default_material) return;
    if (auto error = check_reflectance(*options.default_material)) fail(path, "default " + *error);
    if (auto error = check_emission(*options.default_material)) fail(path, "default " + *error);
}

// Validates every face in file order and returns its material.
std::vector<Material> validate(const LoadedObj& obj, const MtlLines& mtl_lines,
                               const LoadOptions& options, const std::string& path) {
    if (obj.faces.empty()) fail(path, "no faces");
    check_default_material(options, path);
    std::vector<Material> materials;
    std::vector<std::vector<int>> id_lists;
    for (const LoadedFace& face : obj.faces) {
        if (auto error = check_face_geometry(face.corners, face.ids)) {
            fail(at(path, face.statement->line), *error);
        }
        materials.push_back(face_material(obj, face, mtl_lines, options, path));
        id_lists.push_back(face.ids);
    }
    if (auto duplicate = find_duplicate_face(id_lists)) {
        const auto [later, earlier] = *duplicate;
        fail(at(path, obj.faces[later].statement->line),
             fmt::format("duplicate face: same vertices as the face on line {}",
                         obj.faces[earlier].statement->line));
    }
    double emitted = 0;
    for (const Material& m : materials) emitted += m.ke.sum();
    if (!(emitted > 0) && options.use == SceneUse::solve) {
        fail(path, "no face emits light (give a material used by a face Ke > 0)");
    }
    return materials;
}

// OpenMesh reports refused faces on omerr; we handle them, so silence it meanwhile.
class QuietOmerr {
  public:
    QuietOmerr() : m_was_enabled(omerr().is_enabled()) { omerr().disable(); }
    ~QuietOmerr() {
        if (m_was_enabled) omerr().enable();
    }
    QuietOmerr(const QuietOmerr&) = delete;
    QuietOmerr& operator=(const QuietOmerr&) = delete;

  private:
    bool m_was_enabled;
};

PatchMesh::Point to_point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

OpenMesh::FaceHandle add_patch(PatchMesh& mesh, const LoadedFace& face,
                               std::vector<OpenMesh::VertexHandle>& handles) {
    std::vector<OpenMesh::VertexHandle> corners;
    for (std::size_t i = 0; i < face.ids.size(); ++i) {
        OpenMesh::VertexHandle& vh = handles[face.ids[i]];
        if (!vh.is_valid()) vh = mesh.add_vertex(to_point(face.corners[i]));
        corners.push_back(vh);
    }
    OpenMesh::FaceHandle fh = mesh.add_face(corners);
    if (fh.is_valid()) return fh;
    // OpenMesh refuses faces that would make the mesh non-manifold (a third face on an edge, a
    // neighbour with the opposite orientation). We keep the geometry anyway: the face gets its
    // own copies of its vertices, so it is simply not connected to its neighbours.
    for (std::size_t i = 0; i < corners.size(); ++i) {
        corners[i] = mesh.add_vertex(to_point(face.corners[i]));
    }
    return mesh.add_face(corners);
}

PatchMesh build_mesh(const LoadedObj& obj, const std::vector<Material>& materials) {
    PatchMesh mesh;
    auto reflectance = reflectance_prop(mesh);
    auto emission = emission_prop(mesh);
    auto source_line = source_line_prop(mesh);
    std::vector<OpenMesh::VertexHandle> handles(obj.points.size());
    QuietOmerr quiet;
    for (std::size_t f = 0; f < obj.faces.size(); ++f) {
        const OpenMesh::FaceHandle fh = add_patch(mesh, obj.faces[f], handles);
        const Material& m = materials[f];
        reflectance[fh] = OpenMesh::Vec3d(m.kd.x(), m.kd.y(), m.kd.z());
        const Eigen::Vector3d e = std::numbers::pi * m.ke;
        emission[fh] = OpenMesh::Vec3d(e.x(), e.y(), e.z());
        source_line[fh] = obj.faces[f].statement->line;
    }
    return mesh;
}

}  // namespace

PatchMesh load_obj(const std::filesystem::path& obj, const LoadOptions& options) {
    const std::string path = obj.string();
    const std::string text = read_text_file(obj);
    const ObjLines lines = scan_obj(text, path);
    MtlLines mtl_lines;
    const std::string mtl_text = read_materials(obj, lines, mtl_lines);
    const tinyobj::ObjReader reader = parse_with_tinyobj(text, mtl_text, path);
    const LoadedObj loaded = load_geometry(reader, lines, path);
    // Measuring geometry: faces without a material get a neutral one.
    LoadOptions effective = options;
    if (options.use == SceneUse::geometry && !options.default_material) {
        effective.default_material = Material{"default", Eigen::Vector3d::Constant(0.5), {0, 0, 0}};
    }
    const std::vector<Material> materials = validate(loaded, mtl_lines, effective, path);
    return build_mesh(loaded, materials);
}

}  // namespace hmcr
