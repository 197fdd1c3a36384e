// SPDX-License-Identifier: Apache-2.0
// read_obj: OBJ + MTL -> polygon soup (docs/design.md §11.2). One pass over the OBJ text reads
// the positions and the faces (each face's corners, the name its `usemtl` gave it, its line);
// then the material libraries its `mtllib` statements name are read (mtl_reader.h), and every
// face's material is looked up among theirs.
#include "meshes/obj_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <set>

#include "common/text_file.h"
#include "meshes/mtl_reader.h"
#include "meshes/obj_lines.h"
#include "meshes/triangulate.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// How many v, vt and vn statements: in the whole file, or read so far.
struct VertexCounts {
    int positions = 0, texcoords = 0, normals = 0;

    int of(std::size_t part) const {
        return part == 0 ? positions : part == 1 ? texcoords : normals;
    }
};

constexpr const char* kAttributeNames[3] = {"vertex", "texture coordinate", "normal"};
constexpr const char* kAttributePlurals[3] = {"vertices", "texture coordinates", "normals"};

// An OBJ index: a non-zero int.
long parse_index(std::string_view text, std::string_view token, const std::string& path, int line) {
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    long value = 0;
    const char* end = digits.data() + digits.size();
    auto [ptr, ec] = std::from_chars(digits.data(), end, value);
    const bool double_sign = digits.size() < text.size() && !digits.empty() && digits[0] == '-';
    if (digits.empty() || double_sign || ec != std::errc{} || ptr != end || value == 0 ||
        value > INT_MAX || value < -INT_MAX) {
        fail_at_line(
            path, line,
            fmt::format("bad vertex reference {} (indices are non-zero integers)", quote(token)));
    }
    return value;
}

// Checks one "v", "v/t", "v//n" or "v/t/n" reference and returns its position's index (from
// 0). Negative indices count back from the statements read so far; positive ones may not
// exceed the file's count of that kind.
std::uint32_t read_reference(std::string_view token, const VertexCounts& so_far,
                             const VertexCounts& total, const std::string& path, int line) {
    const std::size_t count = std::size_t(std::count(token.begin(), token.end(), '/')) + 1;
    std::array<std::string_view, 3> parts;
    std::string_view rest = token;
    for (std::size_t i = 0; i < std::min<std::size_t>(count, 3); ++i) {
        const std::size_t slash = rest.find('/');
        parts[i] = rest.substr(0, slash);
        rest.remove_prefix(slash == std::string_view::npos ? rest.size() : slash + 1);
    }
    const bool shape_ok = count <= 3 && !(count == 2 && parts[1].empty());
    if (!shape_ok) fail_at_line(path, line, fmt::format("bad vertex reference {}", quote(token)));
    long position = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (i == 1 && parts[i].empty()) continue;  // "v//n"
        const long k = parse_index(parts[i], token, path, line);
        if (k > total.of(i) || -k > so_far.of(i)) {
            fail_at_line(path, line,
                         fmt::format("{} reference {} is out of range ({} {})", kAttributeNames[i],
                                     quote(token), k > 0 ? total.of(i) : so_far.of(i),
                                     kAttributePlurals[i]));
        }
        if (i == 0) position = k > 0 ? k - 1 : so_far.positions + k;
    }
    return std::uint32_t(position);
}

// Counts the statements of each kind first: positive indices may refer further down.
VertexCounts count_vertices(std::string_view text) {
    VertexCounts count;
    for_each_line(without_bom(text), [&](int, std::string_view line) {
        const std::string_view key = Statement(line).keyword();
        if (key == "v") ++count.positions;
        if (key == "vt") ++count.texcoords;
        if (key == "vn") ++count.normals;
    });
    return count;
}

// One `mtllib` statement: the material library files it names, as written.
struct MtllibStatement {
    int line = 0;
    std::vector<std::string> files;
};

// The OBJ being read. Until the libraries are read, a face's material is the index of the
// name its `usemtl` gave it in m_usemtl_names (or kNoMaterial).
class ObjReader {
public:
    ObjReader(const fs::path& obj, std::string_view text)
        : m_obj(obj), m_path(obj.string()), m_total(count_vertices(text)) {
        m_soup.files.push_back(obj);
        m_soup.positions.reserve(std::size_t(m_total.positions));
        for_each_statement(text, m_path, [&](int line, Statement& s) { statement(line, s); });
    }

    PolygonSoup finish() {
        MaterialNames defined;
        read_libraries(defined);
        assign_materials(defined);
        return std::move(m_soup);
    }

private:
    void statement(int line, Statement& s) {
        const std::string_view key = s.keyword();
        if (key == "v") {
            vertex(line, s);
        } else if (key == "f") {
            face(line, s);
        } else if (key == "vt" || key == "vn" || key == "vp") {
            numbers(key, 1, 4, line, s, nullptr);
            if (key == "vt") ++m_so_far.texcoords;
            if (key == "vn") ++m_so_far.normals;
        } else if (key == "l" || key == "p") {
            // Not used, but their references are checked as a face's are.
            for (std::string_view t = s.next(); !t.empty(); t = s.next()) {
                read_reference(t, m_so_far, m_total, m_path, line);
            }
        } else if (key == "usemtl") {
            usemtl(line, s.rest_trimmed());
        } else if (key == "mtllib") {
            MtllibStatement m{line, {}};
            for (std::string_view t = s.next(); !t.empty(); t = s.next()) m.files.emplace_back(t);
            if (m.files.empty()) fail_at_line(m_path, line, "'mtllib' needs a name");
            m_mtllibs.push_back(std::move(m));
        } else if (key != "o" && key != "g" && key != "s") {
            fail_at_line(m_path, line, fmt::format("unknown OBJ statement {}", quote(key)));
        }
    }

    // min to max numbers, the first three (if xyz is given) into xyz.
    void numbers(std::string_view key, std::size_t min, std::size_t max, int line, Statement& s,
                 Eigen::Vector3d* xyz) {
        const std::size_t found = Statement(s).count_rest();
        if (found < min || found > max) {
            fail_at_line(
                m_path, line,
                fmt::format("'{}' needs {} to {} numbers, found {}", key, min, max, found));
        }
        for (std::size_t n = 0; n < found; ++n) {
            const double value = parse_obj_number(s.next(), m_path, line);
            if (xyz && n < 3) (*xyz)[Eigen::Index(n)] = value;
        }
    }

    // x y z, then w or r g b, which hmcr does not use.
    void vertex(int line, Statement& s) {
        Eigen::Vector3d xyz;
        numbers("v", 3, 7, line, s, &xyz);
        m_soup.positions.push_back(xyz);
        ++m_so_far.positions;
    }

    void face(int line, Statement& s) {
        m_corners.clear();
        for (std::string_view t = s.next(); !t.empty(); t = s.next()) {
            if (m_corners.size() == kMaxPolygonCorners) {
                fail_at_line(m_path, line, too_many_corners(m_corners.size() + 1 + s.count_rest()));
            }
            m_corners.push_back(read_reference(t, m_so_far, m_total, m_path, line));
        }
        if (m_corners.size() < 3) {
            fail_at_line(m_path, line,
                         fmt::format("polygon with {} vertices: a face needs 3", m_corners.size()));
        }
        m_soup.add_polygon(m_corners, m_usemtl, {0, std::uint32_t(line)});
    }

    void usemtl(int line, std::string_view name) {
        if (name.empty()) fail_at_line(m_path, line, "'usemtl' needs a name");
        auto it = m_usemtl_index.find(name);
        if (it == m_usemtl_index.end()) {
            it = m_usemtl_index.emplace(std::string(name), std::int32_t(m_usemtl_names.size()))
                     .first;
            m_usemtl_names.push_back(&it->first);
        }
        m_usemtl = it->second;
    }

    // The first existing file of every mtllib statement (of `mtllib a.mtl b.mtl`, the first
    // that exists), each read once; a statement none of whose files exists is an error.
    void read_libraries(MaterialNames& defined) {
        std::set<std::string> loaded;
        for (const MtllibStatement& statement : m_mtllibs) {
            const auto name = std::find_if(
                statement.files.begin(), statement.files.end(), [&](const std::string& n) {
                    std::error_code ec;
                    return loaded.count(n) != 0 || fs::exists(m_obj.parent_path() / n, ec);
                });
            if (name == statement.files.end()) {
                fail_at_line(m_path, statement.line,
                             fmt::format("cannot read material library {}: no such file",
                                         quote(statement.files.front())));
            }
            if (!loaded.insert(*name).second) continue;
            const fs::path path = m_obj.parent_path() / *name;
            std::string text;
            try {
                text = read_text_file(path);
            } catch (const InputError& e) {
                fail_at_line(m_path, statement.line, fmt::format("material library: {}", e.what()));
            }
            m_soup.files.push_back(path);
            read_mtl(text, std::uint32_t(m_soup.files.size() - 1), m_soup, defined);
        }
    }

    // Each face's material: the library's of its name, else an undefined material of that
    // name, added when a face first uses it (an error only if a face without a default
    // material uses it).
    void assign_materials(const MaterialNames& defined) {
        std::vector<std::int32_t> soup_index(m_usemtl_names.size(), PolygonSoup::kNoMaterial);
        for (std::int32_t& material : m_soup.material) {
            if (material == PolygonSoup::kNoMaterial) continue;
            std::int32_t& index = soup_index[std::size_t(material)];
            if (index == PolygonSoup::kNoMaterial) {
                const std::string& name = *m_usemtl_names[std::size_t(material)];
                if (auto it = defined.find(name); it != defined.end()) {
                    index = it->second.index;
                } else {
                    index = std::int32_t(m_soup.materials.size());
                    m_soup.materials.push_back(
                        {Material{name, {0, 0, 0}, {0, 0, 0}}, false, {}, {}, {}});
                }
            }
            material = index;
        }
    }

    const fs::path& m_obj;
    std::string m_path;
    VertexCounts m_total, m_so_far;
    PolygonSoup m_soup;
    std::vector<std::uint32_t> m_corners;  // the face being read
    std::int32_t m_usemtl = PolygonSoup::kNoMaterial;
    std::map<std::string, std::int32_t, std::less<>> m_usemtl_index;  // into m_usemtl_names
    std::vector<const std::string*> m_usemtl_names;
    std::vector<MtllibStatement> m_mtllibs;
};

}  // namespace

PolygonSoup read_obj(const fs::path& obj) {
    const std::string text = read_text_file(obj);
    return ObjReader(obj, text).finish();
}

}  // namespace hmcr
