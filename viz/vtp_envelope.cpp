// SPDX-License-Identifier: Apache-2.0
// check_vtp_envelope (vtp_envelope.h): the XML part by vtp_header.h, then every appended array's
// header against the bytes that are really there, then every cell section's offsets against
// its connectivity.
#include "viz/vtp_envelope.h"

#include <fmt/format.h>
#include <vtkBase64Utilities.h>
#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkSmartPointer.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/error.h"
#include "common/text_file.h"
#include "viz/vtp_header.h"

namespace hmcr {
namespace {

std::uint64_t read_uint(std::string_view bytes, std::size_t at, std::size_t width) {
    std::uint64_t v = 0;
    if (width == 4) {
        std::uint32_t w;
        std::memcpy(&w, bytes.data() + at, 4);
        v = w;
    } else {
        std::memcpy(&v, bytes.data() + at, 8);
    }
    return v;  // the header reader refuses files that are not little-endian
}

// Bytes as a file stores them: raw, or base64 text (decode() says how an array is encoded).
struct Stored {
    std::string_view bytes;
    bool base64 = false;
    // Bytes in the file of n bytes of data.
    std::uint64_t size(std::uint64_t n) const { return base64 ? (n + 2) / 3 * 4 : n; }
};

// An integer type of VTK: its bytes and whether it is signed.
struct IntType {
    std::size_t width = 0;
    bool is_signed = false;
};

std::optional<IntType> int_type(std::string_view type) {
    static const std::pair<std::string_view, IntType> kTypes[] = {{"Int8", {1, true}},
                                                                  {"UInt8", {1, false}},
                                                                  {"Char", {1, true}},
                                                                  {"SignedChar", {1, true}},
                                                                  {"UnsignedChar", {1, false}},
                                                                  {"Int16", {2, true}},
                                                                  {"UInt16", {2, false}},
                                                                  {"Short", {2, true}},
                                                                  {"UnsignedShort", {2, false}},
                                                                  {"Int32", {4, true}},
                                                                  {"UInt32", {4, false}},
                                                                  {"Int", {4, true}},
                                                                  {"UnsignedInt", {4, false}},
                                                                  {"Int64", {8, true}},
                                                                  {"UInt64", {8, false}},
                                                                  {"Long", {8, true}},
                                                                  {"UnsignedLong", {8, false}},
                                                                  {"LongLong", {8, true}},
                                                                  {"UnsignedLongLong", {8, false}},
                                                                  {"IdType", {8, true}}};
    for (const auto& [name, t] : kTypes) {
        if (name == type) return t;
    }
    return std::nullopt;
}

// What a cell array's values hold: the largest, and whether one is below 0.
struct Extent {
    std::uint64_t largest = 0;
    bool negative = false;
    void add(std::uint64_t v) { largest = std::max(largest, v); }
};

class Envelope {
public:
    Envelope(const std::filesystem::path& path, std::string bytes)
        : m_path(path.string()), m_bytes(std::move(bytes)) {}

    [[noreturn]] void fail(const std::string& why) const {
        throw InputError(m_path, "damaged VTK file: " + why);
    }

    void check() {
        const VtpHeader header = read_vtp_header(m_path, m_bytes);
        m_compressed = header.compressed;
        m_width = header.header_width;
        m_compressor = header.compressor;
        if (header.data != std::string_view::npos) {
            const Stored appended{std::string_view(m_bytes).substr(header.data + 1), header.base64};
            m_appended = appended;
            for (const std::uint64_t offset : header.offsets) check_array(appended, offset);
        }
        check_cells(header.cell_arrays);
        for (const VtpStringArray& a : header.string_arrays) check_strings(a);
    }

private:
    // An array: [block count, block size, last block size, compressed sizes...] then the
    // blocks when compressed, else [byte count] then the bytes.
    void check_array(const Stored& s, std::uint64_t offset) const {
        const std::uint64_t left = s.bytes.size();
        const std::size_t width = m_width;
        auto need = [&](std::uint64_t bytes, const char* what) {
            if (offset > left || bytes > left - offset) {
                fail(fmt::format("the array at offset {} declares {} beyond the file's end", offset,
                                 what));
            }
        };
        if (!m_compressed) {
            need(s.size(width), "its size");
            const std::uint64_t size = read_uint(decode(s, offset, width), 0, width);
            if (size > left) need(left + 1, "its values");
            need(s.size(width + size), "its values");  // encoded together
            return;
        }
        need(s.size(3 * width), "its header");
        const std::string head = decode(s, offset, 3 * width);
        const std::uint64_t blocks = read_uint(head, 0, width);
        const std::uint64_t block_size = read_uint(head, width, width);
        const std::uint64_t last_size = read_uint(head, 2 * width, width);
        // VTK 9.1 dereferences null for a header of no blocks but some bytes (fuzzer).
        if (blocks == 0 ? last_size != 0 : block_size == 0 || last_size > block_size) {
            fail(
                fmt::format("the array at offset {} has a block header that contradicts itself "
                            "({} blocks of {} bytes, the last {})",
                            offset, blocks, block_size, last_size));
        }
        if (blocks > left / width) need(left + 1, "its block sizes");
        const std::uint64_t header_bytes = (3 + blocks) * width;
        need(s.size(header_bytes), "its block sizes");
        const std::string sizes = decode(s, offset, header_bytes);
        std::uint64_t stored = 0;
        for (std::uint64_t k = 0; k < blocks && stored <= left; ++k) {
            stored += read_uint(sizes, (3 + k) * width, width);
        }
        if (stored > left) need(left + 1, "its compressed blocks");
        need(s.size(header_bytes) + s.size(stored), "its compressed blocks");
        if (double(block_size) * double(blocks) > kMaxVtpExpansion * double(stored) + 1e6) {
            fail(fmt::format("the array at offset {} declares {} bytes from {} compressed", offset,
                             double(block_size) * double(blocks), stored));
        }
    }

    // A compressed array's header: its blocks' uncompressed size, the last one's (0: as the
    // others) and each one's compressed size.
    struct Blocks {
        std::uint64_t size = 0, last = 0;
        std::vector<std::uint64_t> stored;
        std::uint64_t header_bytes = 0;  // of the header itself
        std::uint64_t bytes(std::size_t k) const {
            return k + 1 == stored.size() && last ? last : size;
        }
    };
    Blocks blocks(const Stored& s, std::uint64_t offset) const {  // check_array first
        const std::string head = decode(s, offset, 3 * m_width);
        const std::uint64_t count = read_uint(head, 0, m_width);
        Blocks b{read_uint(head, m_width, m_width),
                 read_uint(head, 2 * m_width, m_width),
                 {},
                 (3 + count) * m_width};
        const std::string sizes = decode(s, offset, b.header_bytes);
        for (std::uint64_t k = 0; k < count; ++k)
            b.stored.push_back(read_uint(sizes, (3 + k) * m_width, m_width));
        return b;
    }

    // The bytes of an array's values once decoded, from its header alone (check_array first).
    std::uint64_t value_bytes(const Stored& s, std::uint64_t offset) const {
        if (!m_compressed) return read_uint(decode(s, offset, m_width), 0, m_width);
        const Blocks b = blocks(s, offset);
        std::uint64_t bytes = 0;
        for (std::size_t k = 0; k < b.stored.size(); ++k) bytes += b.bytes(k);
        return bytes;
    }

    // An array's values, decoded and decompressed (check_array first).
    std::string values(const Stored& s, std::uint64_t offset, const std::string& what) const {
        if (!m_compressed) {  // the size and the values are encoded together
            return decode(s, offset, m_width + value_bytes(s, offset)).substr(m_width);
        }
        const Blocks b = blocks(s, offset);
        std::uint64_t stored = 0;
        for (const std::uint64_t n : b.stored) stored += n;
        const std::string packed = decode(s, offset + s.size(b.header_bytes), stored);
        const vtkSmartPointer<vtkDataCompressor> compressor = make_compressor();
        std::string out;
        std::uint64_t at = 0;
        for (std::size_t k = 0; k < b.stored.size(); ++k) {
            const std::uint64_t size = b.bytes(k);
            const std::size_t start = out.size();
            out.resize(start + size);
            if (compressor->Uncompress(
                    reinterpret_cast<const unsigned char*>(packed.data() + at), b.stored[k],
                    reinterpret_cast<unsigned char*>(out.data() + start), size) != size) {
                fail(what + " do not decompress");
            }
            at += b.stored[k];
        }
        return out;
    }

    vtkSmartPointer<vtkDataCompressor> make_compressor() const {
        if (m_compressor == "vtkZLibDataCompressor")
            return vtkSmartPointer<vtkZLibDataCompressor>::New();
        if (m_compressor == "vtkLZ4DataCompressor")
            return vtkSmartPointer<vtkLZ4DataCompressor>::New();
        if (m_compressor == "vtkLZMADataCompressor")
            return vtkSmartPointer<vtkLZMADataCompressor>::New();
        fail("compressor " + quote(m_compressor) + " is none of VTK's");
    }

    // VTK makes a cell array's connectivity as long as its last offset says: every offset must
    // lie within the connectivity the file holds.
    void check_cells(const std::vector<VtpCellArray>& arrays) const {
        // A section's arrays are neighbours; VTK reads the first of each name.
        for (std::size_t i = 0; i < arrays.size(); ++i) {
            if (i > 0 && arrays[i - 1].group == arrays[i].group) continue;
            const VtpCellArray* offsets = nullptr;
            const VtpCellArray* connectivity = nullptr;
            for (std::size_t j = i; j < arrays.size() && arrays[j].group == arrays[i].group; ++j) {
                const VtpCellArray*& first = arrays[j].offsets ? offsets : connectivity;
                if (!first) first = &arrays[j];
            }
            const std::string& section = arrays[i].section;
            if (!offsets || !connectivity) {
                fail(fmt::format("its {} have {} but no {}", section,
                                 offsets ? "offsets" : "connectivity",
                                 offsets ? "connectivity" : "offsets"));
            }
            const std::uint64_t held = value_count(*connectivity);
            const Extent reach = extent(*offsets);
            if (reach.negative) fail(fmt::format("its {} offsets hold a negative offset", section));
            if (reach.largest > held) {
                fail(fmt::format("its {} offsets reach {}, but its connectivity holds {} values",
                                 section, reach.largest, held));
            }
        }
    }

    // VTK keeps each string of a String array up to its '\0': the values must end one string
    // for each place the array has.
    void check_strings(const VtpStringArray& a) const {
        std::uint64_t ends = 0;
        bool ended = true;  // the values so far end a string
        if (a.format == "ascii") {
            ascii_values(a.text, "String array " + quote(a.name), [&](std::uint64_t v, bool) {
                ends += v == 0;
                ended = v == 0;
            });
        } else {
            const Stored s = a.format == "appended" ? m_appended : inline_binary(a.text);
            if (a.format == "binary") check_array(s, 0);
            const std::string bytes = values(s, a.offset, "String array " + quote(a.name));
            ends = std::uint64_t(std::count(bytes.begin(), bytes.end(), '\0'));
            ended = bytes.empty() || bytes.back() == '\0';
        }
        if (ends != a.strings || !ended) {
            fail(fmt::format("String array {} holds {} strings{}; it has places for {}",
                             quote(a.name), ends, ended ? "" : " and more", a.strings));
        }
    }

    IntType integers(const VtpCellArray& a) const {
        const auto type = int_type(a.type);
        if (!type) {
            fail(fmt::format("its {} {} are of type {}, not integers", a.section, name(a),
                             quote(a.type)));
        }
        return *type;
    }
    static const char* name(const VtpCellArray& a) {
        return a.offsets ? "offsets" : "connectivity";
    }
    static std::string what(const VtpCellArray& a) {
        return fmt::format("{} {}", a.section, name(a));
    }

    // An inline binary array: its text without the white space before it.
    static Stored inline_binary(std::string_view text) {
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
            text.remove_prefix(1);
        }
        return {text, true};
    }

    std::uint64_t value_count(const VtpCellArray& a) const {
        const IntType type = integers(a);
        if (a.format == "ascii") {
            std::uint64_t n = 0;
            ascii_values(a.text, what(a), [&](std::uint64_t, bool) { ++n; });
            return n;
        }
        const Stored s = a.format == "appended" ? m_appended : inline_binary(a.text);
        if (a.format == "binary") check_array(s, 0);
        return value_bytes(s, a.offset) / type.width;
    }

    Extent extent(const VtpCellArray& a) const {
        const IntType type = integers(a);
        Extent e;
        if (a.format == "ascii") {
            ascii_values(a.text, what(a), [&](std::uint64_t v, bool negative) {
                e.negative |= negative;
                e.add(v);
            });
            return e;
        }
        const Stored s = a.format == "appended" ? m_appended : inline_binary(a.text);
        if (a.format == "binary") check_array(s, 0);
        const std::string bytes = values(s, a.offset, fmt::format("its {} offsets", a.section));
        for (std::size_t at = 0; at + type.width <= bytes.size(); at += type.width) {
            std::uint64_t v = 0;
            std::memcpy(&v, bytes.data() + at, type.width);
            const bool negative = type.is_signed && (v >> (8 * type.width - 1)) & 1;
            e.negative |= negative;
            if (!negative) e.add(v);
        }
        return e;
    }

    // Calls f(value, negative) for each number of an ascii array's text; refuses anything else.
    template <class F>
    void ascii_values(std::string_view text, const std::string& what, F f) const {
        while (true) {
            const std::size_t first = text.find_first_not_of(" \t\r\n\v\f");
            if (first == std::string_view::npos) return;
            text.remove_prefix(first);
            const std::size_t length = std::min(text.find_first_of(" \t\r\n\v\f"), text.size());
            const std::string_view word = text.substr(0, length);
            const bool negative = word.front() == '-';
            std::uint64_t v = 0;
            const auto digits = word.substr(negative ? 1 : 0);
            const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
            if (ec != std::errc() || end != digits.data() + digits.size()) {
                fail(fmt::format("its {} hold {}, not an integer", what,
                                 quote(std::string(word.substr(0, 40)))));
            }
            f(v, negative && v != 0);
            text.remove_prefix(length);
        }
    }

    // The n bytes at `at`: as stored, or decoded from base64, where a compressed array's header
    // and its blocks are encoded each on its own, an uncompressed array's size and values
    // together; either way the first 4 ceil(n / 3) characters at `at` hold the first n bytes.
    std::string decode(const Stored& s, std::uint64_t at, std::uint64_t n) const {
        const std::uint64_t chars = s.size(n);
        if (at > s.bytes.size() || chars > s.bytes.size() - at)
            fail("an array runs past the file's end");
        if (!s.base64) return std::string(s.bytes.substr(at, n));
        std::string out(n + 3, '\0');
        vtkBase64Utilities::DecodeSafely(
            reinterpret_cast<const unsigned char*>(s.bytes.data() + at), chars,
            reinterpret_cast<unsigned char*>(out.data()), out.size());
        out.resize(n);
        return out;
    }

    std::string m_path;
    std::string m_bytes;
    Stored m_appended;          // the appended data, if any
    bool m_compressed = false;  // arrays are in compressed blocks
    std::size_t m_width = 4;    // bytes of each number of an array's header
    std::string m_compressor;   // VTK's compressor class
};

}  // namespace

void check_vtp_envelope(const std::filesystem::path& path) {
    Envelope(path, read_text_file(path)).check();
}

}  // namespace hmcr
