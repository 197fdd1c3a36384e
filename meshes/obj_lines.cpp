// Lexical pre-scan of OBJ and MTL text (see obj_lines.h for why it exists). The grammar accepted
// here is deliberately a strict subset of what tinyobjloader reads, so that every statement we
// accept means the same thing to tinyobjloader and the k-th `v`/`f` we count is its k-th.
#include "meshes/obj_lines.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>

#include "common/text_file.h"
#include "meshes/scene.h"

namespace hmcr {
namespace {

// Spaces and tabs: the only separators tinyobjloader knows.
bool is_separator(char c) { return c == ' ' || c == '\t'; }

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

// How many v, vt and vn statements: in the whole file, or read so far.
struct VertexCounts {
    int positions = 0, texcoords = 0, normals = 0;

    int of(std::size_t part) const { return part == 0 ? positions : part == 1 ? texcoords : normals; }
};

constexpr const char* kAttributeNames[3] = {"vertex", "texture coordinate", "normal"};
constexpr const char* kAttributePlurals[3] = {"vertices", "texture coordinates", "normals"};

// Checks one "v", "v/t", "v//n" or "v/t/n" reference. Negative indices count back from the
// statements read so far; positive ones may not exceed the file's count of that kind.
void check_reference(std::string_view token, const VertexCounts& so_far, const VertexCounts& total,
                     const std::string& path, int line) {
    const std::size_t count = std::size_t(std::count(token.begin(), token.end(), '/')) + 1;
    std::array<std::string_view, 3> parts;
    std::string_view rest = token;
    for (std::size_t i = 0; i < std::min<std::size_t>(count, 3); ++i) {
        const std::size_t slash = rest.find('/');
        parts[i] = rest.substr(0, slash);
        rest.remove_prefix(slash == std::string_view::npos ? rest.size() : slash + 1);
    }
    const bool shape_ok = count <= 3 && !(count == 2 && parts[1].empty());
    if (!shape_ok) fail(path, line, fmt::format("bad vertex reference {}", quote(token)));
    for (std::size_t i = 0; i < count; ++i) {
        if (i == 1 && parts[i].empty()) continue;  // "v//n"
        const long k = parse_index(parts[i], token, path, line);
        if (k > total.of(i) || -k > so_far.of(i)) {
            fail(path, line,
                 fmt::format("{} reference {} is out of range ({} {})", kAttributeNames[i],
                             quote(token), k > 0 ? total.of(i) : so_far.of(i),
                             kAttributePlurals[i]));
        }
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

void check_face(const std::vector<std::string_view>& tokens, const VertexCounts& so_far,
                const VertexCounts& total, const std::string& path, int line) {
    const int n = static_cast<int>(tokens.size()) - 1;
    for (int i = 1; i <= n; ++i) check_reference(tokens[i], so_far, total, path, line);
    if (n < 3) fail(path, line, fmt::format("polygon with {} vertices: a face needs 3", n));
}

// The OBJ scan's state: counts so far and in all, the material in effect, the result.
struct ObjScan {
    const std::string& path;
    VertexCounts total, so_far;
    std::string usemtl;
    ObjLines out;
};

// Handles one OBJ statement.
void scan_obj_statement(const std::vector<std::string_view>& tokens, int line, ObjScan& scan) {
    const std::string_view key = tokens[0];
    const std::string& path = scan.path;
    if (key == "v") {
        check_numbers(tokens, 3, 7, path, line);  // x y z [w] or x y z r g b
        ++scan.so_far.positions;
    } else if (key == "vt" || key == "vn" || key == "vp") {
        check_numbers(tokens, 1, 4, path, line);
        if (key == "vt") ++scan.so_far.texcoords;
        if (key == "vn") ++scan.so_far.normals;
    } else if (key == "f") {
        check_face(tokens, scan.so_far, scan.total, path, line);
        scan.out.faces.push_back({line, scan.usemtl});
    } else if (key == "l" || key == "p") {
        // Ignored by hmcr, but tinyobjloader rejects bad references in them without a line.
        for (std::size_t i = 1; i < tokens.size(); ++i) {
            check_reference(tokens[i], scan.so_far, scan.total, path, line);
        }
    } else if (key == "usemtl" || key == "mtllib") {
        if (tokens.size() < 2) fail(path, line, fmt::format("'{}' needs a name", key));
        if (key == "usemtl") {
            scan.usemtl = std::string(tokens[1]);
        } else {
            scan.out.mtllibs.push_back({line, {tokens.begin() + 1, tokens.end()}});
        }
    } else if (key != "o" && key != "g" && key != "s") {
        fail(path, line, fmt::format("unknown OBJ statement {}", quote(key)));
    }
}

// The first token of a line: the statement's keyword.
std::string_view first_token(std::string_view line) {
    std::size_t start = 0;
    while (start < line.size() && is_separator(line[start])) ++start;
    std::size_t end = start;
    while (end < line.size() && !is_separator(line[end])) ++end;
    return line.substr(start, end - start);
}

// Counts the statements of each kind first: positive indices may refer further down.
VertexCounts count_vertices(std::string_view text) {
    VertexCounts count;
    for_each_line(text, [&](int, std::string_view line) {
        const std::string_view key = first_token(line);
        if (key == "v") ++count.positions;
        if (key == "vt") ++count.texcoords;
        if (key == "vn") ++count.normals;
    });
    return count;
}

void reject_nul(std::string_view line, const std::string& path, int line_number) {
    if (line.find('\0') != std::string_view::npos) {
        fail(path, line_number, "binary data (NUL byte) in a text file");
    }
}

// tinyobjloader names a material by the rest of the `newmtl` line after one separator; we
// insist on a single word so that `usemtl NAME` (which reads one word) can find it. A name
// defined twice is refused: tinyobjloader would silently keep the first.
MtlMaterialLines& define_material(const std::vector<std::string_view>& tokens, int line,
                                  const std::string& path, MtlLines& lines) {
    if (tokens.size() != 2) fail(path, line, "newmtl needs one material name without spaces");
    const std::string name(tokens[1]);
    auto [it, inserted] = lines.try_emplace(name, MtlMaterialLines{path, line, 0, 0});
    if (!inserted) {
        fail(path, line, fmt::format("material {} is defined again (first at {})", quote(name),
                                     at(it->second.file, it->second.newmtl_line)));
    }
    return it->second;
}

// The MTL statements of the common readers; hmcr uses Kd and Ke and ignores the others.
bool is_known_mtl_statement(std::string_view key) {
    static constexpr std::string_view kKnown[] = {
        "Ka", "Ks", "Kt", "Tf", "Ns", "Ni", "d", "Tr", "illum", "sharpness", "bump", "disp",
        "decal", "refl", "norm", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor"};
    if (key.rfind("map_", 0) == 0) return true;
    return std::find(std::begin(kKnown), std::end(kKnown), key) != std::end(kKnown);
}

// The tokens of a line up to a comment: '#' at the start of a token starts one.
void statement_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
    split_tokens(line, tokens);
    const auto comment = std::find_if(tokens.begin(), tokens.end(),
                                      [](std::string_view t) { return t.front() == '#'; });
    tokens.erase(comment, tokens.end());
}

// Calls visit(number, tokens) for every line of the text without its byte-order mark and its
// comments, and appends the cleaned line (its tokens) to `clean`.
void for_each_clean_line(
    std::string_view text, const std::string& path,
    const std::function<void(int, const std::vector<std::string_view>&)>& visit,
    std::string& clean) {
    std::vector<std::string_view> tokens;  // one buffer for every line
    clean.reserve(clean.size() + text.size() + 1);  // not grown by doubling: fresh pages cost
    for_each_line(without_bom(text), [&](int number, std::string_view line) {
        reject_nul(line, path, number);
        statement_tokens(line, tokens);
        visit(number, tokens);
        for (std::size_t i = 0; i < tokens.size(); ++i) {
            clean.append(i ? " " : "").append(tokens[i]);
        }
        clean.push_back('\n');
    });
}

}  // namespace

// Plain loops: std::string_view::find_first_of calls memchr on its set for every character,
// which was 6% of loading a 10^6-face OBJ.
void for_each_line(std::string_view text, const std::function<void(int, std::string_view)>& visit) {
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = start;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        visit(++number, text.substr(start, end - start));
        if (end == text.size()) break;
        const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
        start = end + (crlf ? 2 : 1);
    }
}

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    for (std::size_t i = 0; i < line.size();) {
        if (is_separator(line[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && !is_separator(line[i])) ++i;
        tokens.push_back(line.substr(start, i - start));
    }
}

std::vector<std::string_view> split_tokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    split_tokens(line, tokens);
    return tokens;
}

ObjLines scan_obj(std::string_view text, const std::string& path) {
    ObjScan scan{path, count_vertices(without_bom(text)), {}, {}, {}};
    for_each_clean_line(text, path, [&](int number, const std::vector<std::string_view>& tokens) {
        if (!tokens.empty()) scan_obj_statement(tokens, number, scan);
    }, scan.out.clean_text);
    return std::move(scan.out);
}

std::string scan_mtl(std::string_view text, const std::string& path, MtlLines& lines,
                     std::vector<std::string>& warnings) {
    MtlMaterialLines ignored;  // statements before the first newmtl set nothing
    MtlMaterialLines* current = &ignored;
    std::string clean;
    for_each_clean_line(text, path, [&](int number, const std::vector<std::string_view>& tokens) {
        if (tokens.empty()) return;
        if (tokens[0] == "newmtl") {
            current = &define_material(tokens, number, path, lines);
        } else if (tokens[0] == "Kd" || tokens[0] == "Ke") {
            if (tokens.size() != 4) {
                fail(path, number, fmt::format("'{}' needs three numbers (r g b)", tokens[0]));
            }
            for (std::size_t i = 1; i < 4; ++i) parse_number(tokens[i], path, number);
            (tokens[0] == "Kd" ? current->kd_line : current->ke_line) = number;
        } else if (!is_known_mtl_statement(tokens[0])) {
            warnings.push_back(fmt::format("{}: unknown MTL statement {} ignored", at(path, number),
                                           quote(tokens[0])));
        }
    }, clean);
    return clean;
}

}  // namespace hmcr
