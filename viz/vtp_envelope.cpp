#include "viz/vtp_envelope.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <regex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <vtkBase64Utilities.h>

#include "common/error.h"
#include "common/text_file.h"

namespace hmcr {
namespace {

// zlib's largest expansion is about 1032:1; anything declaring more cannot be in the file.
constexpr double kMaxRatio = 1100;

std::uint64_t read_uint(const std::string& bytes, std::size_t at, std::size_t width) {
    std::uint64_t v = 0;
    if (width == 4) {
        std::uint32_t w;
        std::memcpy(&w, bytes.data() + at, 4);
        v = w;
    } else {
        std::memcpy(&v, bytes.data() + at, 8);
    }
    return v;  // hmcr writes little-endian, as every machine it runs on
}

class Envelope {
public:
    Envelope(const std::filesystem::path& path, std::string bytes)
        : m_path(path.string()),
          m_bytes(std::move(bytes)),
          m_appended(m_bytes.find("<AppendedData")),
          m_xml(m_bytes.substr(0, m_appended)),
          m_base64(m_appended != std::string::npos &&
                   m_bytes.compare(m_appended, kBase64Tag.size(), kBase64Tag) == 0) {}

    [[noreturn]] void fail(const std::string& why) const {
        throw InputError(m_path, "damaged VTK file: " + why);
    }

    void check() const {
        check_elements();
        check_counts();
        check_types();
        check_points();
        if (m_appended == std::string::npos) return;
        // The marker is the first character after the tag and its white space, as VTK reads
        // it: with other bytes before a '_', VTK took one of them for the marker and read every
        // header two bytes off (a 3 GB allocation, found by the fuzzer).
        const std::size_t tag_end = m_bytes.find('>', m_appended);
        const std::size_t data = tag_end == std::string::npos
                                     ? std::string::npos
                                     : m_bytes.find_first_not_of(" \t\r\n", tag_end + 1);
        if (data == std::string::npos || m_bytes[data] != '_') {
            fail("appended data without its '_' marker");
        }
        const bool compressed = !attributes("compressor").empty();
        const auto header_type = attributes("header_type");
        const std::size_t width = !header_type.empty() && header_type[0].second == "UInt64" ? 8 : 4;
        // Every offset, however written: VTK reads offset="19i" as 19, into another array's
        // bytes (a 2.7 GB, 26 s header, found by the fuzzer), so only plain numbers pass.
        for (const auto& [name, value] : attributes("offset")) {
            check_array(data + 1, plain_number(name, value, 19), compressed, width);
        }
    }

private:
    // Every value of an XML attribute of this name (or of names matching it), with either
    // quote and spaces around '=' as XML allows: {name, value} pairs.
    std::vector<std::pair<std::string, std::string>> attributes(const std::string& name) const {
        const std::regex attribute("\\b(" + name + R"re()\s*=\s*(?:"([^"]*)"|'([^']*)'))re");
        std::vector<std::pair<std::string, std::string>> out;
        for (auto it = std::sregex_iterator(m_xml.begin(), m_xml.end(), attribute);
             it != std::sregex_iterator(); ++it) {
            out.emplace_back((*it)[1].str(), (*it)[(*it)[2].matched ? 2 : 3].str());
        }
        return out;
    }

    // A count or offset as hmcr writes it: digits, perhaps spaces around them, at most
    // max_digits of them (anything else VTK would read its own way, or overflow on).
    std::uint64_t plain_number(const std::string& name, const std::string& value,
                               std::size_t max_digits) const {
        static const std::regex plain(R"(\s*(\d+)\s*)");
        std::smatch m;
        if (!std::regex_match(value, m, plain) || m[1].length() > std::ptrdiff_t(max_digits)) {
            fail(fmt::format("{} is {}, not a plain number", name, quote(value)));
        }
        return std::stoull(m[1].str());
    }

    void check_counts() const {
        const double limit = kMaxRatio * double(m_bytes.size()) + 1e6;
        // More than 15 digits is beyond any file.
        for (const auto& [name, value] : attributes(R"(NumberOf\w+)")) {
            if (double(plain_number(name, value, 15)) > limit) {
                fail(fmt::format("{} is {} in a file of {} bytes", name, quote(value),
                                 m_bytes.size()));
            }
        }
    }

    // VTK 9.1 dereferences a null array for an unknown type name (type="Float65": a crash in
    // vtkXMLReader::ReadXMLInformation, found by the fuzzer) and for an array without a type
    // (the fuzzer again), so every array must name one of VTK's own types.
    void check_types() const {
        static const std::regex array(R"(<(?:Data)?Array\b[^>]*>)");
        static const std::regex type(R"re(\btype\s*=\s*(?:"([^"]*)"|'([^']*)'))re");
        static const std::regex known(
            "(U?Int(8|16|32|64)|Float(32|64)|String|Bit|Char|SignedChar|UnsignedChar|Short|"
            "UnsignedShort|Int|UnsignedInt|Long|UnsignedLong|LongLong|UnsignedLongLong|IdType)");
        for (auto it = std::sregex_iterator(m_xml.begin(), m_xml.end(), array);
             it != std::sregex_iterator(); ++it) {
            const std::string element = it->str();
            std::smatch m;
            if (!std::regex_search(element, m, type)) fail("an array without a type");
            const std::string name = m[m[1].matched ? 1 : 2].str();
            if (!std::regex_match(name, known)) fail("an array of unknown type " + quote(name));
        }
    }

    // VTK 9.1 reads every child of FieldData, PointData, ... as an array, and dereferences
    // null for one of another name (`<Dattr ...>`, found by the fuzzer): only the elements a
    // .vtp holds pass (InformationKey and Value: what ParaView adds when it saves one again).
    void check_elements() const {
        static const std::regex element(R"(<([A-Za-z_][\w.:-]*))");
        static const std::regex known(
            "VTKFile|PolyData|Piece|FieldData|PointData|CellData|Points|Verts|Lines|Strips|Polys|"
            "DataArray|Array|AppendedData|InformationKey|Value");
        for (auto it = std::sregex_iterator(m_xml.begin(), m_xml.end(), element);
             it != std::sregex_iterator(); ++it) {
            if (!std::regex_match((*it)[1].str(), known)) {
                fail("an element " + quote((*it)[1].str()) + " that no .vtp of hmcr holds");
            }
        }
    }

    // VTK 9.1 refuses points of other than 3 components but leaks the array it read (found
    // by the fuzzer with LeakSanitizer): refused here first.
    void check_points() const {
        static const std::regex points(R"(<Points>\s*<DataArray\b([^>]*)>)");
        static const std::regex components(
            R"re(\bNumberOfComponents\s*=\s*(?:"\s*3\s*"|'\s*3\s*'))re");
        std::smatch m;
        if (std::regex_search(m_xml, m, points) &&
            !std::regex_search(m[1].first, m[1].second, components)) {
            fail("its points do not have 3 components");
        }
    }

    // An appended array: [block count, block size, last block size, compressed sizes...] then
    // the blocks when compressed, else [byte count] then the bytes.
    void check_array(std::size_t base, std::uint64_t offset, bool compressed,
                     std::size_t width) const {
        const std::uint64_t left = m_bytes.size() - std::min<std::uint64_t>(base, m_bytes.size());
        auto need = [&](std::uint64_t bytes, const char* what) {
            if (offset > left || bytes > left - offset) {
                fail(fmt::format("the array at offset {} declares {} beyond the file's end",
                                 offset, what));
            }
        };
        const std::size_t at = base + offset;
        if (!compressed) {
            need(stored_size(width), "its size");
            const std::uint64_t size = read_uint(header(at, width), 0, width);
            if (size > left) need(left + 1, "its values");
            need(stored_size(width) + stored_size(size), "its values");
            return;
        }
        need(stored_size(3 * width), "its header");
        const std::string head = header(at, 3 * width);
        const std::uint64_t blocks = read_uint(head, 0, width);
        const std::uint64_t block_size = read_uint(head, width, width);
        const std::uint64_t last_size = read_uint(head, 2 * width, width);
        // VTK 9.1 dereferences null for a header of no blocks but some bytes (fuzzer).
        if (blocks == 0 ? last_size != 0 : block_size == 0 || last_size > block_size) {
            fail(fmt::format("the array at offset {} has a block header that contradicts itself "
                             "({} blocks of {} bytes, the last {})",
                             offset, blocks, block_size, last_size));
        }
        if (blocks > left / width) need(left + 1, "its block sizes");
        const std::uint64_t header_bytes = (3 + blocks) * width;
        need(stored_size(header_bytes), "its block sizes");
        const std::string sizes = header(at, header_bytes);
        std::uint64_t stored = 0;
        for (std::uint64_t k = 0; k < blocks && stored <= left; ++k) {
            stored += read_uint(sizes, (3 + k) * width, width);
        }
        if (stored > left) need(left + 1, "its compressed blocks");
        need(stored_size(header_bytes) + stored_size(stored), "its compressed blocks");
        if (double(block_size) * double(blocks) > kMaxRatio * double(stored) + 1e6) {
            fail(fmt::format("the array at offset {} declares {} bytes from {} compressed", offset,
                             double(block_size) * double(blocks), stored));
        }
    }

    // The n bytes of a header at `at`: as stored, or decoded from base64 (a header is encoded
    // on its own, so its first 4 ceil(n / 3) characters hold it).
    std::string header(std::size_t at, std::uint64_t n) const {
        if (!m_base64) return m_bytes.substr(at, n);
        std::string out(n + 3, '\0');
        const std::size_t chars = stored_size(n);
        if (at + chars > m_bytes.size()) fail("a header runs past the file's end");
        vtkBase64Utilities::DecodeSafely(reinterpret_cast<const unsigned char*>(m_bytes.data() + at),
                                         chars, reinterpret_cast<unsigned char*>(out.data()),
                                         out.size());
        out.resize(n);
        return out;
    }
    // Bytes in the file of n bytes of data.
    std::uint64_t stored_size(std::uint64_t n) const { return m_base64 ? (n + 2) / 3 * 4 : n; }

    static constexpr std::string_view kBase64Tag = "<AppendedData encoding=\"base64\"";

    std::string m_path;
    std::string m_bytes;
    std::size_t m_appended;  // where <AppendedData starts, or npos
    std::string m_xml;       // everything before it
    bool m_base64;           // the appended data is base64 text, not raw bytes
};

}  // namespace

void check_vtp_envelope(const std::filesystem::path& path) {
    Envelope(path, read_text_file(path)).check();
}

}  // namespace hmcr
