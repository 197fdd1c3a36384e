// build_patch_mesh: a polygon soup -> the validated OpenMesh patch mesh with its hmcr:* face
// properties (SPEC section 1).
#include <fmt/format.h>

#include <OpenMesh/Core/System/omstream.hh>
#include <array>
#include <map>
#include <numbers>

#include "meshes/polygon_soup.h"
#include "meshes/validation.h"

namespace hmcr {
namespace {

// One polygon with welded vertex ids (equal positions share one id) and its corners.
struct WeldedFace {
    std::vector<int> ids;
    std::vector<Eigen::Vector3d> corners;
};

// Welds exactly equal positions: faces that share a corner position share a vertex id, which
// becomes one OpenMesh vertex, so neighbouring patches are adjacent in the mesh.
std::vector<int> weld(const std::vector<Eigen::Vector3d>& positions, std::size_t& welded_count) {
    std::map<std::array<double, 3>, int> index;
    std::vector<int> id(positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k) {
        const Eigen::Vector3d& p = positions[k];
        id[k] = index.try_emplace({p.x(), p.y(), p.z()}, int(index.size())).first->second;
    }
    welded_count = index.size();
    return id;
}

WeldedFace welded_face(const PolygonSoup& soup, std::size_t k, const std::vector<int>& id) {
    WeldedFace face;
    for (std::uint32_t c : soup.corners(k)) {
        face.ids.push_back(id[c]);
        face.corners.push_back(soup.positions[c]);
    }
    return face;
}

void check_material(const PolygonSoup& soup, const SoupMaterial& m) {
    if (auto error = check_reflectance(m.material)) throw InputError(soup.where(m.kd), *error);
    if (auto error = check_emission(m.material)) throw InputError(soup.where(m.ke), *error);
}

// The material of polygon k: its own (checked), else the default, else an error.
Material face_material(const PolygonSoup& soup, std::size_t k, const LoadOptions& options) {
    const std::int32_t id = soup.material[k];
    if (id != PolygonSoup::kNoMaterial && soup.materials[std::size_t(id)].defined) {
        const SoupMaterial& m = soup.materials[std::size_t(id)];
        check_material(soup, m);
        return m.material;
    }
    if (options.default_material) return *options.default_material;
    const std::string where = soup.where(soup.place[k]);
    if (id == PolygonSoup::kNoMaterial) throw InputError(where, "face has no material (no usemtl before it)");
    throw InputError(where, fmt::format("face uses material {}, which no loaded material file "
                                        "defines",
                                        quote(soup.materials[std::size_t(id)].material.name)));
}

void check_default_material(const LoadOptions& options, const std::string& path) {
    if (!options.default_material) return;
    if (auto error = check_reflectance(*options.default_material)) {
        throw InputError(path, "default " + *error);
    }
    if (auto error = check_emission(*options.default_material)) {
        throw InputError(path, "default " + *error);
    }
}

void check_duplicates(const PolygonSoup& soup, const std::vector<WeldedFace>& faces) {
    std::vector<std::vector<int>> ids;
    for (const WeldedFace& f : faces) ids.push_back(f.ids);
    if (auto duplicate = find_duplicate_face(ids)) {
        const auto [later, earlier] = *duplicate;
        const SourcePlace a = soup.place[later], b = soup.place[earlier];
        throw InputError(soup.where(a),
                         a.file == b.file
                             ? fmt::format("duplicate face: same vertices as the face on line {}", b.line)
                             : fmt::format("duplicate face: same vertices as the face at {}", soup.where(b)));
    }
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

OpenMesh::FaceHandle add_patch(PatchMesh& mesh, const WeldedFace& face,
                               std::vector<OpenMesh::VertexHandle>& handles) {
    std::vector<OpenMesh::VertexHandle> corners;
    for (std::size_t i = 0; i < face.ids.size(); ++i) {
        OpenMesh::VertexHandle& vh = handles[std::size_t(face.ids[i])];
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

PatchMesh make_mesh(const PolygonSoup& soup, const std::vector<WeldedFace>& faces,
                    const std::vector<Material>& materials, std::size_t vertex_count) {
    PatchMesh mesh;
    auto reflectance = reflectance_prop(mesh);
    auto emission = emission_prop(mesh);
    auto source_line = source_line_prop(mesh);
    std::vector<OpenMesh::VertexHandle> handles(vertex_count);
    QuietOmerr quiet;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const OpenMesh::FaceHandle fh = add_patch(mesh, faces[f], handles);
        const Material& m = materials[f];
        reflectance[fh] = OpenMesh::Vec3d(m.kd.x(), m.kd.y(), m.kd.z());
        const Eigen::Vector3d e = std::numbers::pi * m.ke;
        emission[fh] = OpenMesh::Vec3d(e.x(), e.y(), e.z());
        source_line[fh] = int(soup.place[f].line);
    }
    return mesh;
}

}  // namespace

void PolygonSoup::add_polygon(std::span<const std::uint32_t> ids, std::int32_t material_id,
                              SourcePlace at) {
    corner_ids.insert(corner_ids.end(), ids.begin(), ids.end());
    corner_offsets.push_back(std::uint32_t(corner_ids.size()));
    material.push_back(material_id);
    place.push_back(at);
}

std::string PolygonSoup::where(SourcePlace p) const {
    const std::string file = p.file < files.size() ? files[p.file].string() : "?";
    return p.line == 0 ? file : at(file, int(p.line));
}

PatchMesh build_patch_mesh(const PolygonSoup& soup, const LoadOptions& options) {
    const std::string top = soup.files.empty() ? "mesh" : soup.files.front().string();
    if (soup.polygon_count() == 0) throw InputError(top, "no faces");
    check_default_material(options, top);
    std::size_t vertex_count = 0;
    const std::vector<int> id = weld(soup.positions, vertex_count);
    std::vector<WeldedFace> faces;
    std::vector<Material> materials;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        faces.push_back(welded_face(soup, k, id));
        if (auto error = check_face_geometry(faces.back().corners, faces.back().ids)) {
            throw InputError(soup.where(soup.place[k]), *error);
        }
        materials.push_back(face_material(soup, k, options));
    }
    check_duplicates(soup, faces);
    double emitted = 0;
    for (const Material& m : materials) emitted += m.ke.sum();
    if (!(emitted > 0) && options.use == SceneUse::solve) {
        throw InputError(top, "no face emits light (give a material used by a face Ke > 0)");
    }
    return make_mesh(soup, faces, materials, vertex_count);
}

}  // namespace hmcr
