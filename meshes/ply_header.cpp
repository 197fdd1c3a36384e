// SPDX-License-Identifier: Apache-2.0
// read_ply_header: the lines up to `end_header` -> PlyHeader (ply_header.h).
#include "meshes/ply_header.h"

#include <fmt/format.h>

#include <charconv>
#include <limits>

#include "meshes/obj_lines.h"

namespace hmcr {
namespace {

struct PlyTypeName {
    std::string_view name;
    PlyType type;
};

constexpr PlyTypeName kPlyTypeNames[] = {
    {"char", PlyType::int8},       {"uchar", PlyType::uint8},    {"short", PlyType::int16},
    {"ushort", PlyType::uint16},   {"int", PlyType::int32},      {"uint", PlyType::uint32},
    {"float", PlyType::float32},   {"double", PlyType::float64}, {"int8", PlyType::int8},
    {"uint8", PlyType::uint8},     {"int16", PlyType::int16},    {"uint16", PlyType::uint16},
    {"int32", PlyType::int32},     {"uint32", PlyType::uint32},  {"float32", PlyType::float32},
    {"float64", PlyType::float64},
};

// A header line longer than this is refused: a name or a comment, never megabytes.
constexpr std::size_t kMaxPlyHeaderLine = 4096;

class PlyHeaderReader {
public:
    PlyHeaderReader(std::string_view bytes, const std::string& path)
        : m_bytes(bytes), m_path(path) {}

    PlyHeader read() {
        if (next_line() != "ply") fail("not a PLY file: its first line is not 'ply'");
        bool format_seen = false;
        for (;;) {
            if (m_offset >= m_bytes.size()) fail("the header has no 'end_header'");
            Statement s(next_line());
            const std::string_view key = s.keyword();
            if (key == "end_header") {
                if (!s.next().empty()) fail("'end_header' takes nothing after it");
                break;
            }
            if (key == "format") {
                if (format_seen) fail("a second 'format' line");
                format(s);
                format_seen = true;
            } else if (key == "element") {
                element(s);
            } else if (key == "property") {
                property(s);
            } else if (key != "comment" && key != "obj_info" && !key.empty()) {
                fail(fmt::format("unknown PLY header line {}", quote(key)));
            }
            if (!format_seen && key != "comment") fail("the header's second line must be 'format'");
        }
        m_header.data_offset = m_offset;
        m_header.data_line = m_line + 1;
        check_counts();
        return std::move(m_header);
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        fail_at_line(m_path, m_line, message);
    }

    // The next line, without its "\n" or "\r\n"; the header is ASCII text.
    std::string_view next_line() {
        ++m_line;
        const std::size_t end = m_bytes.find('\n', m_offset);
        const std::size_t stop = end == std::string_view::npos ? m_bytes.size() : end;
        std::string_view line = m_bytes.substr(m_offset, stop - m_offset);
        m_offset = end == std::string_view::npos ? m_bytes.size() : end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.size() > kMaxPlyHeaderLine) {
            fail(fmt::format("a header line of {} bytes: at most {}", line.size(),
                             kMaxPlyHeaderLine));
        }
        for (const char c : line) {
            if (c == '\0') fail("a NUL byte in the header");
        }
        return line;
    }

    void format(Statement& s) {
        const std::string_view name = s.next();
        const std::string_view version = s.next();
        if (name == "ascii") {
            m_header.format = PlyFormat::ascii;
        } else if (name == "binary_little_endian") {
            m_header.format = PlyFormat::binary_little_endian;
        } else if (name == "binary_big_endian") {
            m_header.format = PlyFormat::binary_big_endian;
        } else {
            fail(
                fmt::format("unknown PLY format {}: hmcr reads ascii, binary_little_endian and "
                            "binary_big_endian",
                            quote(name)));
        }
        if (version != "1.0" || !s.next().empty()) fail("the format line must end in '1.0'");
    }

    void element(Statement& s) {
        PlyElement e;
        e.name = std::string(s.next());
        const std::string_view count = s.next();
        if (e.name.empty() || count.empty() || !s.next().empty()) {
            fail("'element' needs a name and a count");
        }
        const char* end = count.data() + count.size();
        const auto [ptr, ec] = std::from_chars(count.data(), end, e.count);
        if (ec != std::errc{} || ptr != end) {
            fail(fmt::format("element count {} is not a non-negative integer", quote(count)));
        }
        for (const PlyElement& other : m_header.elements) {
            if (other.name == e.name) fail(fmt::format("a second element {}", quote(e.name)));
        }
        e.line = m_line;
        m_header.elements.push_back(std::move(e));
    }

    PlyType type(std::string_view name) const {
        for (const PlyTypeName& t : kPlyTypeNames) {
            if (t.name == name) return t.type;
        }
        fail(fmt::format("unknown property type {}", quote(name)));
    }

    void property(Statement& s) {
        if (m_header.elements.empty()) fail("a property before the first element");
        PlyProperty p;
        std::string_view first = s.next();
        if (first == "list") {
            p.list = true;
            p.count_type = type(s.next());
            if (!is_ply_integer(p.count_type)) fail("a list's count type must be an integer type");
            first = s.next();
        }
        p.type = type(first);
        p.name = std::string(s.next());
        if (p.name.empty() || !s.next().empty()) fail("'property' needs a type and a name");
        PlyElement& e = m_header.elements.back();
        if (e.find(p.name) >= 0) {
            fail(fmt::format("element {} has a second property {}", quote(e.name), quote(p.name)));
        }
        e.properties.push_back(std::move(p));
    }

    // Every element's instances must fit in the bytes after the header, at their smallest.
    void check_counts() const {
        const std::uint64_t left = m_bytes.size() - m_header.data_offset;
        std::uint64_t needed = 0;
        for (const PlyElement& e : m_header.elements) {
            if (e.properties.empty() && e.count > 0) {
                fail_at_line(m_path, e.line,
                             fmt::format("element {} has no properties", quote(e.name)));
            }
            std::uint64_t smallest = 0;  // bytes of one instance
            for (const PlyProperty& p : e.properties) {
                smallest += m_header.format == PlyFormat::ascii
                                ? 2
                                : std::uint64_t(ply_type_bytes(p.list ? p.count_type : p.type));
            }
            if (smallest == 0) continue;  // an element without instances or properties
            if (e.count > std::numeric_limits<std::uint32_t>::max() ||
                e.count > (left - needed) / smallest) {
                fail_at_line(m_path, e.line,
                             fmt::format("element {} declares {} instances, more than the {} "
                                         "bytes after the header hold",
                                         quote(e.name), e.count, left));
            }
            needed += e.count * smallest;
        }
    }

    std::string_view m_bytes;
    const std::string& m_path;
    std::size_t m_offset = 0;
    int m_line = 0;
    PlyHeader m_header;
};

}  // namespace

int ply_type_bytes(PlyType type) {
    switch (type) {
        case PlyType::int8:
        case PlyType::uint8:
            return 1;
        case PlyType::int16:
        case PlyType::uint16:
            return 2;
        case PlyType::int32:
        case PlyType::uint32:
        case PlyType::float32:
            return 4;
        case PlyType::float64:
            return 8;
    }
    return 8;
}

bool is_ply_integer(PlyType type) { return type != PlyType::float32 && type != PlyType::float64; }

std::string_view ply_type_name(PlyType type) {
    for (const PlyTypeName& t : kPlyTypeNames) {
        if (t.type == type) return t.name;
    }
    return "?";
}

int PlyElement::find(std::string_view property) const {
    for (std::size_t i = 0; i < properties.size(); ++i) {
        if (properties[i].name == property) return int(i);
    }
    return -1;
}

PlyHeader read_ply_header(std::string_view bytes, const std::string& path) {
    return PlyHeaderReader(bytes, path).read();
}

}  // namespace hmcr
