// SPDX-License-Identifier: Apache-2.0
// check_vtp_envelope (vtp_envelope.h): the XML part by vtp_header.h, then every appended array's
// header against the bytes that are really there.
#include "viz/vtp_envelope.h"

#include <fmt/format.h>
#include <vtkBase64Utilities.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "common/error.h"
#include "common/text_file.h"
#include "viz/vtp_header.h"

namespace hmcr {
namespace {

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
        : m_path(path.string()), m_bytes(std::move(bytes)) {}

    [[noreturn]] void fail(const std::string& why) const {
        throw InputError(m_path, "damaged VTK file: " + why);
    }

    void check() {
        const VtpHeader header = read_vtp_header(m_path, m_bytes);
        if (header.data == std::string_view::npos) return;
        m_base64 = header.base64;
        for (const std::uint64_t offset : header.offsets) {
            check_array(header.data + 1, offset, header.compressed, header.header_width);
        }
    }

private:
    // An appended array: [block count, block size, last block size, compressed sizes...] then
    // the blocks when compressed, else [byte count] then the bytes.
    void check_array(std::size_t base, std::uint64_t offset, bool compressed,
                     std::size_t width) const {
        const std::uint64_t left = m_bytes.size() - std::min<std::uint64_t>(base, m_bytes.size());
        auto need = [&](std::uint64_t bytes, const char* what) {
            if (offset > left || bytes > left - offset) {
                fail(fmt::format("the array at offset {} declares {} beyond the file's end", offset,
                                 what));
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
            fail(
                fmt::format("the array at offset {} has a block header that contradicts itself "
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
        if (double(block_size) * double(blocks) > kMaxVtpExpansion * double(stored) + 1e6) {
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
        vtkBase64Utilities::DecodeSafely(
            reinterpret_cast<const unsigned char*>(m_bytes.data() + at), chars,
            reinterpret_cast<unsigned char*>(out.data()), out.size());
        out.resize(n);
        return out;
    }
    // Bytes in the file of n bytes of data.
    std::uint64_t stored_size(std::uint64_t n) const { return m_base64 ? (n + 2) / 3 * 4 : n; }

    std::string m_path;
    std::string m_bytes;
    bool m_base64 = false;  // the appended data is base64 text, not raw bytes
};

}  // namespace

void check_vtp_envelope(const std::filesystem::path& path) {
    Envelope(path, read_text_file(path)).check();
}

}  // namespace hmcr
