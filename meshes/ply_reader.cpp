// SPDX-License-Identifier: Apache-2.0
// read_ply: PLY header and data -> polygon soup (ply_reader.h). The header is read first
// (ply_header.h), then the elements in their order, one instance at a time (ply_cursor.h).
#include "meshes/ply_reader.h"

#include <fmt/format.h>

#include <array>
#include <map>

#include "common/text_file.h"
#include "meshes/obj_lines.h"
#include "meshes/ply_cursor.h"
#include "meshes/ply_header.h"
#include "meshes/triangulate.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// The colour properties of an element: reflectance (red, green, blue) and emission
// (emission_red, ...), each three indices into its properties or absent.
struct ColourProperties {
    std::array<int, 3> kd{-1, -1, -1}, ke{-1, -1, -1};
    bool has_kd() const { return kd[0] >= 0; }
    bool has_ke() const { return ke[0] >= 0; }
};

class PlyReader {
public:
    PlyReader(const fs::path& ply, std::string_view bytes)
        : m_path(ply.string()),
          m_header(read_ply_header(bytes, m_path)),
          m_cursor(bytes, m_header, m_path) {
        m_soup.files.push_back(ply);
        if (!m_cursor.ascii()) m_soup.item_names[0] = "face";
        m_soup.no_material = "the PLY has no colour or emission properties";
    }

    PolygonSoup read() {
        const PlyElement* vertex = find("vertex");
        const PlyElement* face = find("face");
        if (vertex == nullptr) fail_at_line(m_path, 1, "the header has no element 'vertex'");
        if (face == nullptr) {
            fail_at_line(m_path, 1,
                         "the header has no element 'face' (a point cloud has no "
                         "polygons)");
        }
        if (face < vertex) {
            fail_at_line(m_path, face->line, "element 'face' comes before element 'vertex'");
        }
        m_vertex_colours = colours(*vertex);
        m_face_colours = colours(*face);
        m_corners_property = face->find("vertex_indices");
        if (m_corners_property < 0) m_corners_property = face->find("vertex_index");
        if (m_corners_property < 0 || !face->properties[std::size_t(m_corners_property)].list ||
            !is_ply_integer(face->properties[std::size_t(m_corners_property)].type)) {
            fail_at_line(m_path, face->line,
                         "element 'face' needs a list of integers 'vertex_indices'");
        }
        for (const char* axis : {"x", "y", "z"}) {
            const int p = vertex->find(axis);
            if (p < 0 || vertex->properties[std::size_t(p)].list) {
                fail_at_line(m_path, vertex->line,
                             fmt::format("element 'vertex' needs a property '{}'", axis));
            }
            m_axes.push_back(p);
        }
        m_materials = m_vertex_colours.has_kd() || m_vertex_colours.has_ke() ||
                      m_face_colours.has_kd() || m_face_colours.has_ke();
        for (const PlyElement& e : m_header.elements) {
            if (&e == vertex) {
                read_vertices(e);
            } else if (&e == face) {
                read_faces(e);
            } else {
                skip(e);
            }
        }
        return std::move(m_soup);
    }

private:
    const PlyElement* find(std::string_view name) const {
        for (const PlyElement& e : m_header.elements) {
            if (e.name == name) return &e;
        }
        return nullptr;
    }

    // The element's colour properties: all three channels or none, of a type hmcr reads.
    ColourProperties colours(const PlyElement& e) const {
        ColourProperties c;
        read_channels(e, "", c.kd, true);
        read_channels(e, "emission_", c.ke, false);
        return c;
    }

    void read_channels(const PlyElement& e, const std::string& prefix, std::array<int, 3>& out,
                       bool bytes_allowed) const {
        const char* channels[3] = {"red", "green", "blue"};
        int found = 0;
        for (int c = 0; c < 3; ++c) {
            const int p = e.find(prefix + channels[c]);
            out[std::size_t(c)] = p;
            if (p < 0) continue;
            ++found;
            const PlyProperty& property = e.properties[std::size_t(p)];
            const bool fits =
                !property.list &&
                (property.type == PlyType::float32 || property.type == PlyType::float64 ||
                 (bytes_allowed && property.type == PlyType::uint8));
            if (!fits) {
                fail_at_line(
                    m_path, e.line,
                    fmt::format("property '{}' of element {} is {}{}: hmcr reads {}", property.name,
                                quote(e.name), property.list ? "a list of " : "",
                                ply_type_name(property.type),
                                bytes_allowed ? "uchar (0-255), float or double (0-1)"
                                              : "float or double (W sr^-1 m^-2)"));
            }
        }
        if (found != 0 && found != 3) {
            fail_at_line(m_path, e.line,
                         fmt::format("element {} has {} of the properties {}red, {}green, "
                                     "{}blue: a colour needs all three",
                                     quote(e.name), found, prefix, prefix, prefix));
        }
    }

    // One instance's values (a list's items are read and dropped, but `corners` gets those of
    // the face's vertex list).
    void values(const PlyElement& e, std::vector<double>& out, int corners_property) {
        out.resize(e.properties.size());
        for (std::size_t p = 0; p < e.properties.size(); ++p) {
            const PlyProperty& property = e.properties[p];
            if (!property.list) {
                out[p] = m_cursor.scalar(property.type);
                continue;
            }
            const std::uint64_t n = m_cursor.count(property.count_type, "list length");
            const bool corners = int(p) == corners_property;
            if (corners && n > kMaxPolygonCorners) m_cursor.fail(too_many_corners(n));
            for (std::uint64_t i = 0; i < n; ++i) {
                if (!corners) {
                    m_cursor.scalar(property.type);
                    continue;
                }
                const std::uint64_t index = m_cursor.count(property.type, "vertex index");
                if (index >= m_soup.positions.size()) {
                    m_cursor.fail(fmt::format("vertex index {} is out of range ({} vertices)",
                                              index, m_soup.positions.size()));
                }
                m_corners.push_back(std::uint32_t(index));
            }
        }
    }

    static Eigen::Vector3d colour(const PlyElement& e, const std::vector<double>& v,
                                  const std::array<int, 3>& channels) {
        Eigen::Vector3d c;
        for (int k = 0; k < 3; ++k) {
            const std::size_t p = std::size_t(channels[std::size_t(k)]);
            c[k] = e.properties[p].type == PlyType::uint8 ? v[p] / 255 : v[p];
        }
        return c;
    }

    void read_vertices(const PlyElement& e) {
        m_soup.positions.reserve(e.count);  // the header's counts are checked against the file
        std::vector<double> v;
        for (std::uint64_t i = 0; i < e.count; ++i) {
            m_cursor.begin(e.name, i);
            values(e, v, -1);
            m_cursor.end();
            m_soup.positions.emplace_back(v[std::size_t(m_axes[0])], v[std::size_t(m_axes[1])],
                                          v[std::size_t(m_axes[2])]);
            if (m_vertex_colours.has_kd()) m_vertex_kd.push_back(colour(e, v, m_vertex_colours.kd));
            if (m_vertex_colours.has_ke()) m_vertex_ke.push_back(colour(e, v, m_vertex_colours.ke));
        }
    }

    // The mean of the face's corners' values.
    Eigen::Vector3d mean(const std::vector<Eigen::Vector3d>& per_vertex) const {
        Eigen::Vector3d sum(0, 0, 0);
        for (const std::uint32_t c : m_corners) sum += per_vertex[c];
        return sum / double(m_corners.size());
    }

    void read_faces(const PlyElement& e) {
        std::vector<double> v;
        for (std::uint64_t i = 0; i < e.count; ++i) {
            m_cursor.begin(e.name, i);
            m_corners.clear();
            values(e, v, m_corners_property);
            m_cursor.end();
            if (m_corners.size() < 3) {
                m_cursor.fail(
                    fmt::format("polygon with {} vertices: a face needs 3", m_corners.size()));
            }
            const SourcePlace at{0, m_cursor.place()};
            std::int32_t material = PolygonSoup::kNoMaterial;
            if (m_materials) {
                Eigen::Vector3d kd(0, 0, 0), ke(0, 0, 0);
                if (m_face_colours.has_kd()) {
                    kd = colour(e, v, m_face_colours.kd);
                } else if (m_vertex_colours.has_kd()) {
                    kd = mean(m_vertex_kd);
                }
                if (m_face_colours.has_ke()) {
                    ke = colour(e, v, m_face_colours.ke);
                } else if (m_vertex_colours.has_ke()) {
                    ke = mean(m_vertex_ke);
                }
                material = material_of(kd, ke, at);
            }
            m_soup.add_polygon(m_corners, material, at);
        }
    }

    // The material of these values: the first face's that had them, else a new one.
    std::int32_t material_of(const Eigen::Vector3d& kd, const Eigen::Vector3d& ke, SourcePlace at) {
        const std::array<double, 6> key{kd.x(), kd.y(), kd.z(), ke.x(), ke.y(), ke.z()};
        const auto [it, inserted] =
            m_material_index.try_emplace(key, std::int32_t(m_soup.materials.size()));
        if (inserted) {
            const std::string name = fmt::format("colour {}", m_soup.materials.size() + 1);
            m_soup.materials.push_back({Material{name, kd, ke}, true, at, at, at});
        }
        return it->second;
    }

    void skip(const PlyElement& e) {
        std::vector<double> v;
        for (std::uint64_t i = 0; i < e.count; ++i) {
            m_cursor.begin(e.name, i);
            values(e, v, -1);
            m_cursor.end();
        }
    }

    std::string m_path;
    PlyHeader m_header;
    PlyCursor m_cursor;
    PolygonSoup m_soup;
    ColourProperties m_vertex_colours, m_face_colours;
    int m_corners_property = -1;
    std::vector<int> m_axes;
    bool m_materials = false;
    std::vector<Eigen::Vector3d> m_vertex_kd, m_vertex_ke;
    std::vector<std::uint32_t> m_corners;  // the face being read
    std::map<std::array<double, 6>, std::int32_t> m_material_index;
};

}  // namespace

PolygonSoup read_ply(const fs::path& ply) {
    const std::string bytes = read_text_file(ply);
    return PlyReader(ply, bytes).read();
}

}  // namespace hmcr
