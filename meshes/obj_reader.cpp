// read_obj: OBJ + MTL -> polygon soup.
//
// Steps: read the files ourselves (so an unreadable MTL is an error, not a warning), pre-scan
// them for line numbers, lexical errors and unknown statements (obj_lines.h), and let
// tinyobjloader parse the cleaned text in double precision without triangulation.
#ifndef TINYOBJLOADER_USE_DOUBLE
#define TINYOBJLOADER_USE_DOUBLE  // the tinyobjloader_double target defines it too
#endif
#include "meshes/obj_reader.h"

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <map>
#include <set>

#include "common/text_file.h"
#include "meshes/obj_lines.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// The text of a material library named by an mtllib statement; its problems are reported at
// the statement.
std::string read_library(const fs::path& path, const fs::path& obj, int line) {
    try {
        return read_text_file(path);
    } catch (const InputError& e) {
        throw InputError(at(obj, line), fmt::format("material library: {}", e.what()));
    }
}

// Reads the first existing file of every mtllib statement (tinyobjloader's rule) and returns
// their cleaned text for tinyobjloader; records where each material was defined and which
// files were read.
std::string read_materials(const fs::path& obj, const ObjLines& lines, MtlLines& mtl_lines,
                           PolygonSoup& soup) {
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
            throw InputError(at(obj, statement.line),
                             fmt::format("cannot read material library {}: no such file",
                                         quote(statement.files.front())));
        }
        if (!loaded.insert(*name).second) continue;
        const fs::path path = obj.parent_path() / *name;
        const std::string mtl = read_library(path, obj, statement.line);
        soup.files.push_back(path);
        text += scan_mtl(mtl, path.string(), mtl_lines, soup.warnings);
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
        throw InputError(path, "tinyobjloader: " + error.substr(0, error.find('\n')));
    }
    return reader;
}

std::uint32_t file_index(const PolygonSoup& soup, const std::string& path) {
    for (std::size_t i = 0; i < soup.files.size(); ++i) {
        if (soup.files[i].string() == path) return std::uint32_t(i);
    }
    return 0;
}

// tinyobjloader's materials, in its order, with the places of their Kd and Ke.
void add_materials(const tinyobj::ObjReader& reader, const MtlLines& mtl_lines,
                   PolygonSoup& soup) {
    for (const tinyobj::material_t& m : reader.GetMaterials()) {
        SoupMaterial out;
        out.material.name = m.name;
        out.material.kd = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        out.material.ke = {m.emission[0], m.emission[1], m.emission[2]};
        if (auto it = mtl_lines.find(m.name); it != mtl_lines.end()) {
            const MtlMaterialLines& l = it->second;
            const std::uint32_t file = file_index(soup, l.file);
            out.kd = {file, std::uint32_t(l.kd_line ? l.kd_line : l.newmtl_line)};
            out.ke = {file, std::uint32_t(l.ke_line ? l.ke_line : l.newmtl_line)};
        }
        soup.materials.push_back(std::move(out));
    }
}

// The soup's material for a face: tinyobjloader's index, else the undefined material its
// usemtl names (reported only if a face without a default material uses it).
std::int32_t face_material(int tinyobj_id, const std::string& usemtl, PolygonSoup& soup,
                           std::map<std::string, std::int32_t>& undefined) {
    if (tinyobj_id >= 0 && std::size_t(tinyobj_id) < soup.materials.size()) return tinyobj_id;
    if (usemtl.empty()) return PolygonSoup::kNoMaterial;
    auto [it, inserted] = undefined.try_emplace(usemtl, std::int32_t(soup.materials.size()));
    if (inserted) soup.materials.push_back({Material{usemtl, {0, 0, 0}, {0, 0, 0}}, false, {}, {}});
    return it->second;
}

void add_polygons(const tinyobj::ObjReader& reader, const ObjLines& lines, PolygonSoup& soup) {
    std::map<std::string, std::int32_t> undefined;
    std::size_t k = 0;
    std::vector<std::uint32_t> ids;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++k) {
            if (k >= lines.faces.size()) throw std::logic_error("tinyobjloader read extra faces");
            ids.clear();
            for (unsigned i = 0; i < shape.mesh.num_face_vertices[f]; ++i, ++offset) {
                const int v = shape.mesh.indices.at(offset).vertex_index;
                if (v < 0 || std::size_t(v) >= soup.positions.size()) {
                    throw std::logic_error("tinyobjloader returned a bad vertex index");
                }
                ids.push_back(std::uint32_t(v));
            }
            const FaceStatement& statement = lines.faces[k];
            soup.add_polygon(ids, face_material(shape.mesh.material_ids[f], statement.usemtl, soup, undefined),
                             {0, std::uint32_t(statement.line)});
        }
    }
    if (k != lines.faces.size()) throw std::logic_error("tinyobjloader missed faces");
}

}  // namespace

PolygonSoup read_obj(const fs::path& obj) {
    PolygonSoup soup;
    soup.files.push_back(obj);
    const std::string path = obj.string();
    const ObjLines lines = scan_obj(read_text_file(obj), path);
    MtlLines mtl_lines;
    const std::string mtl_text = read_materials(obj, lines, mtl_lines, soup);
    const tinyobj::ObjReader reader = parse_with_tinyobj(lines.clean_text, mtl_text, path);
    const std::vector<tinyobj::real_t>& xyz = reader.GetAttrib().vertices;
    soup.positions.reserve(xyz.size() / 3);
    for (std::size_t k = 0; k + 2 < xyz.size(); k += 3) {
        soup.positions.emplace_back(xyz[k], xyz[k + 1], xyz[k + 2]);
    }
    add_materials(reader, mtl_lines, soup);
    add_polygons(reader, lines, soup);
    return soup;
}

}  // namespace hmcr
