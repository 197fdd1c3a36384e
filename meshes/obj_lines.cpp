// Lexical pre-scan of OBJ and MTL text (see obj_lines.h for why it exists). The grammar accepted
// here is deliberately a strict subset of what tinyobjloader reads, so that every statement we
// accept means the same thing to tinyobjloader and the k-th `v`/`f` we count is its k-th.
#include "meshes/obj_lines.h"

#include <fmt/format.h>

#include <charconv>
#include <climits>
#include <cmath>

#include "meshes/scene.h"

namespace hmcr {
namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& message) {
    throw InputError(at(path, line), message);
}

// A finite decimal number; tinyobjloader's own parser reads "nan", "inf" and "1x" as 0, so they
// must be caught here. A leading '+' is valid OBJ but not from_chars syntax.
double parse_number(std::string_view token, const std::string& path, int line) {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const char* end = digits.data() + digits.size();
    auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
    if (digits.size() < token.size() && (digits.empty() || digits.front() == '-')) {
        ec = std::errc::invalid_argument;  // "+-1": tinyobjloader would read 0
    }
    if (ec == std::errc::result_out_of_range) {
        fail(path, line, fmt::format("number {} is out of range", quote(token)));
    }
    if (ec != std::errc{} || ptr != end) {
        fail(path, line, fmt::format("cannot parse number {}", quote(token)));
    }
    if (!std::isfinite(value)) {
        fail(path, line, fmt::format("{} is not a finite number", quote(token)));
    }
    return value;
}

// An OBJ index: a non-zero int (tinyobjloader reads it with atoi, so it must fit an int).
long parse_index(std::string_view text, std::string_view token, const std::string& path, int line) {
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    long value = 0;
    const char* end = digits.data() + digits.size();
    auto [ptr, ec] = std::from_chars(digits.data(), end, value);
    const bool double_sign = digits.size() < text.size() && !digits.empty() && digits[0] == '-';
    if (digits.empty() || double_sign || ec != std::errc{} || ptr != end || value == 0 ||
        value > INT_MAX || value < -INT_MAX) {
        fail(path, line,
             fmt::format("bad vertex reference {} (indices are non-zero integers)", quote(token)));
    }
    return value;
}

// Checks one "v", "v/t", "v//n" or "v/t/n" reference. Negative indices count back from the
// vertices read so far; positive ones may not exceed the file's vertex count.
void check_reference(std::string_view token, int vertices_so_far, int vertex_total,
                     const std::string& path, int line) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t slash = token.find('/'); slash != std::string_view::npos;
         slash = token.find('/', start)) {
        parts.push_back(token.substr(start, slash - start));
        start = slash + 1;
    }
    parts.push_back(token.substr(start));
    const bool shape_ok = parts.size() <= 3 && !(parts.size() == 2 && parts[1].empty());
    if (!shape_ok) fail(path, line, fmt::format("bad vertex reference {}", quote(token)));
    for (std::size_t i = 1; i < parts.size(); ++i) {
        if (i == 1 && parts[i].empty()) continue;  // "v//n"
        parse_index(parts[i], token, path, line);
    }
    const long v = parse_index(parts[0], token, path, line);
    if (v > vertex_total || -v > vertices_so_far) {
        fail(path, line,
             fmt::format("vertex reference {} is out of range ({} vertices)", quote(token),
                         v > 0 ? vertex_total : vertices_so_far));
    }
}

void check_numbers(const std::vector<std::string_view>& tokens, std::size_t min, std::size_t max,
                   const std::string& path, int line) {
    const std::size_t count = tokens.size() - 1;
    if (count < min || count > max) {
        fail(path, line,
             fmt::format("'{}' needs {} to {} numbers, found {}", tokens[0], min, max, count));
    }
    for (std::size_t i = 1; i < tokens.size(); ++i) parse_number(tokens[i], path, line);
}

void check_face(const std::vector<std::string_view>& tokens, const ObjLines& lines,
                int vertex_total, const std::string& path, int line) {
    const int n = static_cast<int>(tokens.size()) - 1;
    for (int i = 1; i <= n; ++i) {
        check_reference(tokens[i], static_cast<int>(lines.vertex_lines.size()), vertex_total, path,
                        line);
    }
    if (n < 3 || n > 4) {
        fail(path, line,
             fmt::format("polygon with {} vertices: hmcr reads triangles and convex "
                         "quads; triangulate it",
                         n));
    }
}

bool is_blank_or_comment(const std::vector<std::string_view>& tokens) {
    return tokens.empty() || tokens[0].front() == '#';
}

// Handles one OBJ statement; `usemtl` is the material in effect, updated here.
void scan_obj_statement(const std::vector<std::string_view>& tokens, int vertex_total,
                        const std::string& path, int line, std::string& usemtl, ObjLines& out) {
    const std::string_view key = tokens[0];
    if (key == "v") {
        check_numbers(tokens, 3, 7, path, line);  // x y z [w] or x y z r g b
        out.vertex_lines.push_back(line);
    } else if (key == "vt" || key == "vn" || key == "vp") {
        check_numbers(tokens, 1, 4, path, line);
    } else if (key == "f") {
        check_face(tokens, out, vertex_total, path, line);
        out.faces.push_back({line, static_cast<int>(tokens.size()) - 1, usemtl});
    } else if (key == "l" || key == "p") {
        // Ignored by hmcr, but tinyobjloader rejects bad references in them without a line.
        for (std::size_t i = 1; i < tokens.size(); ++i) {
            check_reference(tokens[i], static_cast<int>(out.vertex_lines.size()), vertex_total,
                            path, line);
        }
    } else if (key == "usemtl" || key == "mtllib") {
        if (tokens.size() < 2) fail(path, line, fmt::format("'{}' needs a name", key));
        if (key == "usemtl") {
            usemtl = std::string(tokens[1]);
        } else {
            out.mtllibs.push_back({line, {tokens.begin() + 1, tokens.end()}});
        }
    } else if (key != "o" && key != "g" && key != "s") {
        fail(path, line, fmt::format("unknown OBJ statement {}", quote(key)));
    }
}

// Counts `v` statements first: positive indices may refer to vertices defined further down.
int count_vertices(std::string_view text) {
    int count = 0;
    for_each_line(text, [&](int, std::string_view line) {
        const auto tokens = split_tokens(line);
        if (!tokens.empty() && tokens[0] == "v") ++count;
    });
    return count;
}

void reject_nul(std::string_view line, const std::string& path, int line_number) {
    if (line.find('\0') != std::string_view::npos) {
        fail(path, line_number, "binary data (NUL byte) in a text file");
    }
}

// tinyobjloader names a material by the rest of the `newmtl` line after one separator; we
// insist on a single word so that `usemtl NAME` (which reads one word) can find it.
std::string material_name(const std::vector<std::string_view>& tokens, std::string_view line,
                          const std::string& path, int line_number) {
    const std::size_t after_key = tokens[0].data() - line.data() + tokens[0].size();
    if (tokens.size() != 2 || tokens[1].data() != line.data() + after_key + 1) {
        fail(path, line_number, "newmtl needs one material name without spaces");
    }
    return std::string(tokens[1]);
}

}  // namespace

void for_each_line(std::string_view text, const std::function<void(int, std::string_view)>& visit) {
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find_first_of("\r\n", start);
        const std::size_t stop = end == std::string_view::npos ? text.size() : end;
        visit(++number, text.substr(start, stop - start));
        if (end == std::string_view::npos) break;
        const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
        start = end + (crlf ? 2 : 1);
    }
}

std::vector<std::string_view> split_tokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t start = line.find_first_not_of(" \t");
    while (start != std::string_view::npos) {
        const std::size_t end = line.find_first_of(" \t", start);
        tokens.push_back(line.substr(start, end == std::string_view::npos ? end : end - start));
        start = end == std::string_view::npos ? end : line.find_first_not_of(" \t", end);
    }
    return tokens;
}

ObjLines scan_obj(std::string_view text, const std::string& path) {
    ObjLines out;
    std::string usemtl;
    const int vertex_total = count_vertices(text);
    for_each_line(text, [&](int number, std::string_view line) {
        reject_nul(line, path, number);
        const auto tokens = split_tokens(line);
        if (!is_blank_or_comment(tokens)) {
            scan_obj_statement(tokens, vertex_total, path, number, usemtl, out);
        }
    });
    return out;
}

void scan_mtl(std::string_view text, const std::string& path, MtlLines& lines) {
    // Statements before the first newmtl, or in a repeated definition of a name, set nothing
    // that tinyobjloader keeps (the first definition of a name wins): they go to `ignored`.
    MtlMaterialLines ignored;
    MtlMaterialLines* current = &ignored;
    for_each_line(text, [&](int number, std::string_view line) {
        reject_nul(line, path, number);
        const auto tokens = split_tokens(line);
        if (is_blank_or_comment(tokens)) return;
        if (tokens[0] == "newmtl") {
            auto [it, inserted] = lines.try_emplace(material_name(tokens, line, path, number),
                                                    MtlMaterialLines{path, number, 0, 0});
            current = inserted ? &it->second : &ignored;
        } else if (tokens[0] == "Kd" || tokens[0] == "Ke") {
            if (tokens.size() != 4) {
                fail(path, number, fmt::format("'{}' needs three numbers (r g b)", tokens[0]));
            }
            for (std::size_t i = 1; i < 4; ++i) parse_number(tokens[i], path, number);
            (tokens[0] == "Kd" ? current->kd_line : current->ke_line) = number;
        }
    });
}

}  // namespace hmcr
