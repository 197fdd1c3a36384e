// SPDX-License-Identifier: Apache-2.0
// build_patch_mesh: a polygon soup -> the validated OpenMesh patch mesh with its hmcr:* face
// properties (docs/design.md §1).
#include <fmt/format.h>

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <array>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <optional>

#include "meshes/polygon_soup.h"
#include "meshes/validation.h"
#include "meshes/weld.h"

namespace hmcr {
namespace {

// Polygon k with welded vertex ids (equal positions share one id) and its corners, into
// buffers the caller reuses (a million faces must not mean two million small vectors).
void welded_face(const PolygonSoup& soup, std::size_t k, const std::vector<int>& id,
                 std::vector<int>& ids, std::vector<Eigen::Vector3d>& corners) {
    ids.clear();
    corners.clear();
    for (std::uint32_t c : soup.corners(k)) {
        ids.push_back(id[c]);
        corners.push_back(soup.positions[c]);
    }
}

// Reflectance 1 is refused only by a strict load (the repairs accepted it with a warning).
void check_material(const PolygonSoup& soup, const SoupMaterial& m, const LoadOptions& options) {
    if (auto error = check_reflectance(m.material, !options.strict)) {
        throw InputError(soup.where(m.kd), *error);
    }
    if (auto error = check_emission(m.material)) throw InputError(soup.where(m.ke), *error);
    if (auto error = check_specular(m.material, !options.strict)) {
        throw InputError(soup.where(m.ks), *error);
    }
}

// Material `id` of polygon k (its front's or its back's): the soup's (checked), else the
// default, else an error at the polygon.
Material face_material(const PolygonSoup& soup, std::int32_t id, std::size_t k,
                       const LoadOptions& options) {
    if (id != PolygonSoup::kNoMaterial && soup.materials[std::size_t(id)].defined) {
        const SoupMaterial& m = soup.materials[std::size_t(id)];
        check_material(soup, m, options);
        return m.material;
    }
    if (options.default_material) return *options.default_material;
    const std::string where = soup.where(soup.place[k]);
    if (id == PolygonSoup::kNoMaterial) {
        throw InputError(where, fmt::format("face has no material ({})", soup.no_material));
    }
    throw InputError(where, fmt::format("face uses material {}, which no loaded material file "
                                        "defines",
                                        quote(soup.materials[std::size_t(id)].material.name)));
}

void check_default_material(const LoadOptions& options, const std::string& path) {
    if (!options.default_material) return;
    if (auto error = check_reflectance(*options.default_material, !options.strict)) {
        throw InputError(path, "default " + *error);
    }
    if (auto error = check_emission(*options.default_material)) {
        throw InputError(path, "default " + *error);
    }
}

// Why a duplicate has no safe repair (the repairs drop one in the same order and material).
std::string duplicate_detail(const PolygonSoup& soup, const std::vector<int>& id, std::size_t later,
                             std::size_t earlier) {
    const auto cyclic = [&](std::size_t k) {
        std::vector<int> ids;
        for (std::uint32_t c : soup.corners(k)) ids.push_back(id[c]);
        std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
        return ids;
    };
    if (soup.material[later] != soup.material[earlier]) return ", with another material";
    if (cyclic(later) != cyclic(earlier)) return ", facing the other way";
    return "";
}

void check_duplicates(const PolygonSoup& soup, const std::vector<int>& id,
                      const std::vector<FaceKey>& keys) {
    if (auto duplicate = find_duplicate_face(keys)) {
        const auto [later, earlier] = *duplicate;
        const SourcePlace a = soup.place[later], b = soup.place[earlier];
        const std::string earlier_at = a.file == b.file
                                           ? fmt::format("on {} {}", soup.item_word(b.file), b.line)
                                           : "at " + soup.where(b);
        throw InputError(soup.where(a),
                         fmt::format("duplicate face: same vertices as the face {}{}", earlier_at,
                                     duplicate_detail(soup, id, later, earlier)));
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

OpenMesh::FaceHandle add_patch(PatchMesh& mesh, const std::vector<int>& ids,
                               const std::vector<Eigen::Vector3d>& points,
                               std::vector<OpenMesh::VertexHandle>& handles,
                               std::vector<OpenMesh::VertexHandle>& corners) {
    corners.clear();
    for (std::size_t i = 0; i < ids.size(); ++i) {
        OpenMesh::VertexHandle& vh = handles[std::size_t(ids[i])];
        if (!vh.is_valid()) vh = mesh.add_vertex(to_point(points[i]));
        corners.push_back(vh);
    }
    OpenMesh::FaceHandle fh = mesh.add_face(corners);
    if (fh.is_valid()) return fh;
    // OpenMesh refuses faces that would make the mesh non-manifold (a third face on an edge, a
    // neighbour with the opposite orientation). We keep the geometry anyway: the face gets its
    // own copies of its vertices, so it is simply not connected to its neighbours.
    for (std::size_t i = 0; i < corners.size(); ++i) {
        corners[i] = mesh.add_vertex(to_point(points[i]));
    }
    return mesh.add_face(corners);
}

// The distinct edges of the welded polygons, so that OpenMesh's edge arrays are reserved
// exactly: an open mesh has more than corners / 2 edges, and an array that grows past its
// reserve keeps twice the room (133 instead of 67 MB on the 10^6-patch office).
std::size_t edge_count(const PolygonSoup& soup, const std::vector<int>& id,
                       std::size_t vertex_count) {
    // Each edge is listed at its lower vertex (a counting sort), and each vertex's short list
    // is sorted on its own, instead of sorting all 4 x 10^6 edge keys at once.
    const auto for_each_edge = [&](auto&& f) {
        for (std::size_t p = 0; p < soup.polygon_count(); ++p) {
            const auto c = soup.corners(p);
            for (std::size_t k = 0; k < c.size(); ++k) {
                const auto a = std::uint32_t(id[c[k]]);
                const auto b = std::uint32_t(id[c[(k + 1) % c.size()]]);
                f(std::min(a, b), std::max(a, b));
            }
        }
    };
    std::vector<std::uint32_t> first(vertex_count + 1, 0);
    for_each_edge([&](std::uint32_t low, std::uint32_t) { ++first[low + 1]; });
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1), high(first.back());
    for_each_edge([&](std::uint32_t low, std::uint32_t h) { high[next[low]++] = h; });
    std::size_t count = 0;
    for (std::size_t v = 0; v < vertex_count; ++v) {
        const auto begin = high.begin() + first[v], end = high.begin() + first[v + 1];
        std::sort(begin, end);
        count += std::size_t(std::unique(begin, end) - begin);
    }
    return count;
}

// The faces' indices into the material table: fronts, and backs (kOneSided for a one-sided
// face; empty when every face is one-sided, and the mesh then has no back property).
struct MaterialIndices {
    std::vector<std::uint32_t> front, back;
};

// `materials[of.front[f]]` is face f's material.
void make_mesh(const PolygonSoup& soup, const std::vector<int>& id,
               const std::vector<Material>& materials, const MaterialIndices& of,
               std::size_t vertex_count, PatchMesh& mesh) {
    mesh.reserve(vertex_count, edge_count(soup, id, vertex_count), soup.polygon_count());
    std::vector<FaceMaterial>& table = *materials_prop(mesh);
    for (const Material& m : materials) {
        const Eigen::Vector3d e = std::numbers::pi * m.ke;
        table.push_back({OpenMesh::Vec3d(m.kd.x(), m.kd.y(), m.kd.z()),
                         OpenMesh::Vec3d(e.x(), e.y(), e.z()),
                         OpenMesh::Vec3d(m.ks.x(), m.ks.y(), m.ks.z()), m.roughness});
    }
    auto material = material_prop(mesh);
    auto source_line = source_line_prop(mesh);
    std::optional<decltype(back_material_prop(mesh))> back;
    if (!of.back.empty()) back = back_material_prop(mesh);
    std::vector<OpenMesh::VertexHandle> handles(vertex_count), corners;
    std::vector<int> ids;
    std::vector<Eigen::Vector3d> points;
    QuietOmerr quiet;
    for (std::size_t f = 0; f < soup.polygon_count(); ++f) {
        welded_face(soup, f, id, ids, points);
        const OpenMesh::FaceHandle fh = add_patch(mesh, ids, points, handles, corners);
        material[fh] = of.front[f];
        if (back) (*back)[fh] = of.back[f];
        source_line[fh] = int(soup.place[f].line);
    }
}

}  // namespace

void PolygonSoup::add_polygon(std::span<const std::uint32_t> ids, std::int32_t material_id,
                              SourcePlace at, std::int32_t back_id) {
    corner_ids.insert(corner_ids.end(), ids.begin(), ids.end());
    corner_offsets.push_back(std::uint32_t(corner_ids.size()));
    material.push_back(material_id);
    back.push_back(back_id);
    place.push_back(at);
}

std::string PolygonSoup::where(SourcePlace p) const {
    std::string file = p.file < files.size() ? files[p.file].string() : "?";
    if (p.line == 0) return file;
    const auto item = item_names.find(p.file);
    if (item != item_names.end()) return fmt::format("{}: {} {}", file, item->second, p.line);
    return at(file, int(p.line));
}

std::string PolygonSoup::item_word(std::uint32_t file) const {
    const auto item = item_names.find(file);
    return item == item_names.end() ? "line" : item->second;
}

void check_positions(const PolygonSoup& soup) {
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        for (std::uint32_t c : soup.corners(k)) {
            if (auto error = check_position(soup.positions[c])) {
                throw InputError(soup.where(soup.place[k]), *error);
            }
        }
    }
}

PatchMesh build_patch_mesh(const PolygonSoup& soup, const LoadOptions& options) {
    PatchMesh mesh;
    build_patch_mesh(soup, weld(soup.positions), options, mesh);
    return mesh;
}

void build_patch_mesh(const PolygonSoup& soup, const Welding& welding, const LoadOptions& options,
                      PatchMesh& mesh) {
    const std::string top = soup.files.empty() ? "mesh" : soup.files.front().string();
    if (soup.polygon_count() == 0) throw InputError(top, "no faces");
    check_default_material(options, top);
    const std::vector<int>& id = welding.id;
    const std::size_t vertex_count = welding.count;
    // Each distinct material is resolved and checked once (at its first face, where an error
    // is reported), then referred to by index.
    std::vector<Material> materials;
    std::vector<std::int64_t> resolved(soup.materials.size() + 1, -1);  // by soup id + 1
    const auto index_of = [&](std::int32_t soup_id, std::size_t k) {
        std::int64_t& slot = resolved[std::size_t(std::int64_t(soup_id) + 1)];
        if (slot < 0) {
            slot = std::int64_t(materials.size());
            materials.push_back(face_material(soup, soup_id, k, options));
        }
        return std::uint32_t(slot);
    };
    MaterialIndices of;
    of.front.resize(soup.polygon_count());
    std::vector<FaceKey> keys(soup.polygon_count());
    std::vector<int> ids;
    std::vector<Eigen::Vector3d> corners;
    double emitted = 0;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        welded_face(soup, k, id, ids, corners);
        if (auto error = check_face_geometry(corners, ids)) {
            throw InputError(soup.where(soup.place[k]), *error);
        }
        keys[k] = face_key(ids);
        of.front[k] = index_of(soup.material[k], k);
        emitted += materials[of.front[k]].ke.sum();
        if (soup.back[k] == PolygonSoup::kOneSided) continue;
        if (of.back.empty()) of.back.assign(soup.polygon_count(), kOneSided);
        of.back[k] = index_of(soup.back[k], k);
        emitted += materials[of.back[k]].ke.sum();
    }
    check_duplicates(soup, id, keys);
    if (!(emitted > 0) && options.use == SceneUse::solve) {
        throw InputError(top, "no face emits light (give a material used by a face Ke > 0)");
    }
    make_mesh(soup, id, materials, of, vertex_count, mesh);
}

}  // namespace hmcr
