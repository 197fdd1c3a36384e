// SPDX-License-Identifier: Apache-2.0
// read_vtp_header (vtp_header.h): expat calls on_start for every element of the XML part, in
// document order; the first problem found stops it.
#include "viz/vtp_header.h"

#include <expat.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <optional>
#include <set>

#include "common/error.h"

namespace hmcr {
namespace {

// The elements a .vtp holds (InformationKey and Value: what ParaView adds when it saves one
// again). VTK 9.1 reads every child of FieldData, PointData, ... as an array and dereferences
// null for one of another name (`<Dattr ...>`, found by the fuzzer).
bool is_vtp_element(std::string_view name) {
    static constexpr std::string_view kKnown[] = {
        "VTKFile", "PolyData",     "Piece",          "FieldData", "PointData", "CellData",
        "Points",  "Verts",        "Lines",          "Strips",    "Polys",     "DataArray",
        "Array",   "AppendedData", "InformationKey", "Value"};
    return std::find(std::begin(kKnown), std::end(kKnown), name) != std::end(kKnown);
}

// VTK's own type names. VTK 9.1 dereferences a null array for an unknown one (type="Float65",
// found by the fuzzer) and for an array without a type (the fuzzer again).
bool is_vtk_type(std::string_view type) {
    static constexpr std::string_view kKnown[] = {"Int8",
                                                  "Int16",
                                                  "Int32",
                                                  "Int64",
                                                  "UInt8",
                                                  "UInt16",
                                                  "UInt32",
                                                  "UInt64",
                                                  "Float32",
                                                  "Float64",
                                                  "String",
                                                  "Bit",
                                                  "Char",
                                                  "SignedChar",
                                                  "UnsignedChar",
                                                  "Short",
                                                  "UnsignedShort",
                                                  "Int",
                                                  "UnsignedInt",
                                                  "Long",
                                                  "UnsignedLong",
                                                  "LongLong",
                                                  "UnsignedLongLong",
                                                  "IdType"};
    return std::find(std::begin(kKnown), std::end(kKnown), type) != std::end(kKnown);
}

bool is_array(std::string_view element) { return element == "DataArray" || element == "Array"; }

// The elements whose arrays VTK reads by name.
bool is_data_section(std::string_view element) {
    return element == "FieldData" || element == "PointData" || element == "CellData";
}

// The elements whose offsets and connectivity make a vtkCellArray.
bool is_cell_section(std::string_view element) {
    return element == "Verts" || element == "Lines" || element == "Strips" || element == "Polys";
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// A count attribute: NumberOfPoints, NumberOfTuples, NumberOfComponents, ...
// An attribute's name as a message shows it: a damaged file's names may be of any length.
std::string shown_name(std::string_view name) {
    constexpr std::size_t kMax = 40;
    return name.size() <= kMax ? std::string(name) : std::string(name.substr(0, kMax)) + "...";
}

bool is_count(std::string_view attribute) {
    constexpr std::string_view kPrefix = "NumberOf";
    return attribute.size() > kPrefix.size() && attribute.substr(0, kPrefix.size()) == kPrefix &&
           std::all_of(attribute.begin() + kPrefix.size(), attribute.end(), [](char c) {
               return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
           });
}

// The XML part being read, and the first problem found in it.
class HeaderReader {
public:
    explicit HeaderReader(std::size_t file_bytes)
        : m_file_bytes(file_bytes), m_limit(kMaxVtpExpansion * double(file_bytes) + 1e6) {
        m_parser.reset(XML_ParserCreate(nullptr));
        if (!m_parser) throw std::bad_alloc();
        XML_SetUserData(m_parser.get(), this);
        XML_SetElementHandler(m_parser.get(), &HeaderReader::on_start, &HeaderReader::on_end);
        XML_SetStartDoctypeDeclHandler(m_parser.get(), &HeaderReader::on_doctype);
        XML_SetCharacterDataHandler(m_parser.get(), &HeaderReader::on_text);
    }

    // Reads the XML; `complete`: it is the whole file (no appended data follows). Returns why
    // it is refused, or "".
    std::string read(std::string_view xml, bool complete) {
        constexpr std::size_t kChunk = std::size_t(1) << 26;  // XML_Parse takes an int
        for (std::size_t at = 0; at < xml.size() || at == 0; at += kChunk) {
            const std::size_t n = std::min(kChunk, xml.size() - at);
            const bool last = at + n == xml.size();
            if (XML_Parse(m_parser.get(), xml.data() + at, int(n), last && complete) ==
                XML_STATUS_ERROR) {
                if (!m_error.empty()) return m_error;
                return fmt::format("XML error at line {}: {}",
                                   XML_GetCurrentLineNumber(m_parser.get()),
                                   XML_ErrorString(XML_GetErrorCode(m_parser.get())));
            }
            if (last) break;
        }
        return m_error;
    }

    VtpHeader header;
    bool appended_tag = false;  // the AppendedData element was read whole

private:
    struct FreeParser {
        void operator()(XML_Parser p) const { XML_ParserFree(p); }
    };

    static void XMLCALL on_start(void* self, const XML_Char* name, const XML_Char** attributes) {
        static_cast<HeaderReader*>(self)->start(name, attributes);
    }
    static void XMLCALL on_end(void* self, const XML_Char* name) {
        HeaderReader& reader = *static_cast<HeaderReader*>(self);
        reader.m_in_points = false;
        reader.m_collecting = nullptr;
        if (is_data_section(name)) reader.m_section.clear();
        if (is_cell_section(name)) reader.m_cell_section.clear();
    }
    static void XMLCALL on_text(void* self, const XML_Char* text, int length) {
        HeaderReader& reader = *static_cast<HeaderReader*>(self);
        if (reader.m_collecting) reader.m_collecting->append(text, length);
    }
    static void XMLCALL on_doctype(void* self, const XML_Char*, const XML_Char*, const XML_Char*,
                                   int) {
        static_cast<HeaderReader*>(self)->refuse("a document type declaration");
    }

    // Stops the parser at the first problem; false, for the checks to return.
    bool refuse(std::string why) {
        if (m_error.empty()) m_error = std::move(why);
        XML_StopParser(m_parser.get(), XML_FALSE);
        return false;
    }

    void start(std::string_view element, const XML_Char** attributes) {
        if (!m_error.empty()) return;
        if (!is_vtp_element(element)) {
            refuse("an element " + quote(element) + " that no .vtp of hmcr holds");
            return;
        }
        for (const XML_Char** a = attributes; *a; a += 2) {
            if (!attribute(a[0], a[1])) return;
        }
        if (element == "AppendedData") {
            appended_tag = true;
            const char* encoding = attribute_value(attributes, "encoding");
            header.base64 = encoding && std::string_view(encoding) == "base64";
        }
        if (is_array(element) && !array_is_readable(attributes)) return;
        if (is_data_section(element)) {
            m_section = element;
            m_section_names.clear();
        }
        if (is_cell_section(element)) {
            m_cell_section = element;
            ++m_cell_groups;
        }
        if (element == "Piece") piece(attributes);
        m_in_points = element == "Points";
    }

    // The counts of a piece, which size its PointData and CellData arrays (checked as counts).
    void piece(const XML_Char** attributes) {
        const auto count = [&](std::string_view name) -> std::uint64_t {
            const char* value = attribute_value(attributes, name);
            return value ? std::stoull(std::string(plain_digits(value))) : 0;
        };
        m_piece_points = count("NumberOfPoints");
        m_piece_cells = count("NumberOfVerts") + count("NumberOfLines") + count("NumberOfStrips") +
                        count("NumberOfPolys");
    }

    // An array's type, the points' components, and the array's name in its data section.
    bool array_is_readable(const XML_Char** attributes) {
        const char* type = attribute_value(attributes, "type");
        if (!type) return refuse("an array without a type");
        if (!is_vtk_type(type)) return refuse("an array of unknown type " + quote(type));
        // VTK 9.1 refuses points of other than 3 components but leaks the array it read
        // (found by the fuzzer with LeakSanitizer): refused here first.
        const char* components = attribute_value(attributes, "NumberOfComponents");
        if (m_in_points && !(components && plain_digits(components) == std::string_view("3"))) {
            return refuse("its points do not have 3 components");
        }
        // VTK 9.1 dereferences null for two arrays of one name in CellData (found by the
        // fuzzer): a name is refused the second time in a data section.
        const char* name = attribute_value(attributes, "Name");
        if (!m_section.empty() && name && !m_section_names.insert(name).second) {
            return refuse(fmt::format("two arrays named {} in its {}", quote(name), m_section));
        }
        // VTK allocates components times tuples, each checked on its own above; an array's
        // tuples are its NumberOfTuples or a count of its piece, at most the largest so far.
        const double values =
            (components ? double(std::stoull(std::string(plain_digits(components)))) : 1.0) *
            double(std::max<std::uint64_t>(m_largest_count, 1));
        if (values > m_limit) {
            return refuse(
                fmt::format("an array of {} components and {} tuples in a file of {} "
                            "bytes",
                            quote(components), m_largest_count, m_file_bytes));
        }
        if (!m_cell_section.empty() && name &&
            (std::string_view(name) == "offsets" || std::string_view(name) == "connectivity")) {
            return cell_array(name, type, attributes);
        }
        if (std::string_view(type) == "String") return string_array(name, attributes);
        return true;
    }

    // Where an array's values are: its format, and its offset when appended.
    bool place(const std::string& what, const XML_Char** attributes, std::string& format,
               std::uint64_t& offset) {
        const char* f = attribute_value(attributes, "format");
        format = f ? f : "";
        if (format == "appended") {
            const char* at = attribute_value(attributes, "offset");
            if (!at) return refuse(fmt::format("its {} have no offset", what));
            offset = std::stoull(std::string(plain_digits(at)));  // checked as read
        } else if (format != "binary" && format != "ascii") {
            return refuse(
                fmt::format("its {} are of format {}, not one VTK reads", what, quote(format)));
        }
        return true;
    }

    // A String array, kept for the envelope's count of its strings. FieldData arrays are sized
    // by their NumberOfTuples, PointData and CellData arrays by their piece.
    bool string_array(const char* name, const XML_Char** attributes) {
        VtpStringArray a;
        a.name = name ? shown_name(name) : "";
        const std::string what = "String array " + quote(a.name) + "'s values";
        if (!place(what, attributes, a.format, a.offset)) return false;
        const char* tuples = attribute_value(attributes, "NumberOfTuples");
        const char* components = attribute_value(attributes, "NumberOfComponents");
        std::uint64_t count = m_section == "PointData" ? m_piece_points : m_piece_cells;
        if (m_section != "PointData" && m_section != "CellData") {
            if (!tuples) {
                return refuse(fmt::format("String array {} has no NumberOfTuples", quote(a.name)));
            }
            count = std::stoull(std::string(plain_digits(tuples)));  // checked as read
        }
        a.strings = count * (components ? std::stoull(std::string(plain_digits(components))) : 1);
        header.string_arrays.push_back(std::move(a));
        if (header.string_arrays.back().format != "appended")
            m_collecting = &header.string_arrays.back().text;
        return true;
    }

    // A cell section's offsets or connectivity, kept for the envelope's check of its values.
    bool cell_array(std::string_view name, const char* type, const XML_Char** attributes) {
        VtpCellArray a;
        a.section = m_cell_section;
        a.group = m_cell_groups;
        a.offsets = name == "offsets";
        a.type = type;
        if (!place(fmt::format("{} {}", a.section, name), attributes, a.format, a.offset))
            return false;
        header.cell_arrays.push_back(std::move(a));
        if (header.cell_arrays.back().format != "appended")
            m_collecting = &header.cell_arrays.back().text;
        return true;
    }

    static const char* attribute_value(const XML_Char** attributes, std::string_view name) {
        for (const XML_Char** a = attributes; *a; a += 2) {
            if (name == a[0]) return a[1];
        }
        return nullptr;
    }

    // Checks one attribute and keeps what the appended arrays' check needs; false: refused.
    bool attribute(std::string_view name, std::string_view value) {
        if (is_count(name)) {
            const auto count = plain_number(name, value, 15);  // more digits: beyond any file
            if (!count) return false;
            if (double(*count) > m_limit) {
                return refuse(fmt::format("{} is {} in a file of {} bytes", shown_name(name),
                                          quote(value), m_file_bytes));
            }
            if (name != "NumberOfComponents") m_largest_count = std::max(m_largest_count, *count);
        } else if (name == "offset") {
            // Every offset, however written: VTK reads offset="19i" as 19, into another array's
            // bytes (a 2.7 GB, 26 s header, found by the fuzzer), so only plain numbers pass.
            const auto offset = plain_number(name, value, 19);
            if (!offset) return false;
            header.offsets.push_back(*offset);
        } else if (name == "byte_order" && value != "LittleEndian") {
            // The checks read headers as hmcr writes them, little-endian.
            return refuse(fmt::format("byte_order is {}, not LittleEndian", quote(value)));
        } else if (name == "compressor") {
            header.compressed = true;
            header.compressor = value;
        } else if (name == "header_type" && !m_header_type_seen) {
            m_header_type_seen = true;
            header.header_width = value == "UInt64" ? 8 : 4;
        }
        return true;
    }

    // The digits of a number written as hmcr writes it, perhaps with spaces around them; ""
    // for anything else.
    static std::string_view plain_digits(std::string_view value) {
        while (!value.empty() && is_space(value.front())) value.remove_prefix(1);
        while (!value.empty() && is_space(value.back())) value.remove_suffix(1);
        const bool digits = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
            return c >= '0' && c <= '9';
        });
        return digits ? value : std::string_view();
    }

    // A count or offset of at most max_digits digits (anything else VTK would read its own
    // way, or overflow on); refused otherwise.
    std::optional<std::uint64_t> plain_number(std::string_view name, std::string_view value,
                                              std::size_t max_digits) {
        const std::string_view digits = plain_digits(value);
        if (digits.empty() || digits.size() > max_digits) {
            refuse(fmt::format("{} is {}, not a plain number", shown_name(name), quote(value)));
            return std::nullopt;
        }
        return std::stoull(std::string(digits));
    }

    std::unique_ptr<XML_ParserStruct, FreeParser> m_parser;
    std::size_t m_file_bytes;
    double m_limit;                         // the largest count the file could hold
    bool m_in_points = false;               // the last element started is a Points
    std::string m_section;                  // the data section being read, if any
    std::set<std::string> m_section_names;  // the names of its arrays so far
    bool m_header_type_seen = false;        // the first header_type counts
    std::uint64_t m_largest_count = 0;      // the largest count of tuples, points or cells so far
    std::string m_cell_section;             // the cell section being read, if any
    std::size_t m_cell_groups = 0;          // cell sections started so far
    std::string* m_collecting = nullptr;    // where the text read goes: an inline array's
    std::uint64_t m_piece_points = 0;       // the piece being read: its NumberOfPoints
    std::uint64_t m_piece_cells = 0;        // and its cells, of every section
    std::string m_error;
};

}  // namespace

VtpHeader read_vtp_header(const std::string& path, std::string_view bytes) {
    const auto fail = [&](const std::string& why) {
        throw InputError(path, "damaged VTK file: " + why);
    };
    // VTK finds the appended data as this does: the first "<AppendedData", its tag ending at the
    // first '>', the marker the first character after it and its white space. With other bytes
    // before a '_', VTK took one of them for the marker and read every header two bytes off (a
    // 3 GB allocation, found by the fuzzer).
    const std::size_t appended = bytes.find("<AppendedData");
    const std::size_t tag_end =
        appended == std::string_view::npos ? std::string_view::npos : bytes.find('>', appended);
    HeaderReader reader(bytes.size());
    const std::size_t xml_end = appended == std::string_view::npos  ? bytes.size()
                                : tag_end == std::string_view::npos ? appended
                                                                    : tag_end + 1;
    const std::string why =
        reader.read(bytes.substr(0, xml_end), appended == std::string_view::npos);
    if (!why.empty()) fail(why);
    VtpHeader header = reader.header;
    if (appended == std::string_view::npos) return header;
    const std::size_t data = tag_end == std::string_view::npos
                                 ? tag_end
                                 : bytes.find_first_not_of(" \t\r\n", tag_end + 1);
    if (!reader.appended_tag || data == std::string_view::npos || bytes[data] != '_') {
        fail("appended data without its '_' marker");
    }
    header.data = data;
    return header;
}

}  // namespace hmcr
