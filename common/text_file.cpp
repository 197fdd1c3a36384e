#include "common/text_file.h"

#include <algorithm>
#include <fstream>
#include <string_view>

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// nlohmann reports the byte offset of a parse error; users want the line.
int line_of_byte(const std::string& text, std::size_t byte) {
    const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + end, '\n'));
}

// nlohmann's message without its "[json.exception.parse_error.101] " tag, and with the token
// it quotes ("last read: '...'", as long as the file's longest string) cut short.
std::string plain_message(const std::exception& e) {
    const std::string what = e.what();
    const std::size_t tag_end = what.rfind("] ", what.find(' '));
    std::string out =
        tag_end == std::string::npos || what.front() != '[' ? what : what.substr(tag_end + 2);
    // Everything after "last read: '" is the token and what follows it ("'; expected ..."),
    // and the token may itself hold "'; expected" (both found by the fuzzer): all of it is
    // quoted, that is, cut short.
    constexpr std::string_view kLastRead = "last read: '";
    const std::size_t token = out.find(kLastRead);
    if (token == std::string::npos) return out;
    return out.substr(0, token) + "last read: " + quote(std::string_view(out).substr(token + kLastRead.size()));
}

// Returns the size the file system gives (0 when it gives none).
std::uintmax_t check_readable(const fs::path& path, std::uint64_t max_bytes) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw InputError(path.string(), "no such file");
    if (fs::is_directory(status)) throw InputError(path.string(), "is a directory");
    if (!fs::is_regular_file(status)) {
        throw InputError(path.string(), "is not a regular file (a device, FIFO or socket)");
    }
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > max_bytes) {
        throw InputError(path.string(), "is " + std::to_string(size) +
                                            " bytes, more than the limit of " +
                                            std::to_string(max_bytes) + " for a text file");
    }
    return ec ? 0 : size;
}

}  // namespace

std::string read_text_file(const fs::path& path, std::uint64_t max_bytes) {
    const std::uintmax_t size = check_readable(path, max_bytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string(), "cannot be read");
    // Read in chunks up to the limit, whatever the size said: a file may grow meanwhile. The
    // size said is reserved: grown by doubling, a 48 MB file was copied 10 times into fresh pages.
    std::string text;
    text.reserve(std::size_t(size));  // at most max_bytes: check_readable refused more
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        text.append(chunk, std::size_t(in.gcount()));
        if (text.size() > max_bytes) {
            throw InputError(path.string(), "grew past the limit of " +
                                                std::to_string(max_bytes) + " bytes while read");
        }
    }
    if (in.bad()) throw InputError(path.string(), "cannot be read");
    return text;
}

nlohmann::json read_json_file(const fs::path& path) {
    constexpr std::uint64_t kMaxJsonBytes = std::uint64_t(256) << 20;
    const std::string text = read_text_file(path, kMaxJsonBytes);
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(at(path, line_of_byte(text, e.byte)), plain_message(e));
    } catch (const nlohmann::json::exception& e) {
        // A number beyond double's range ("1e400") is an out_of_range, with no position.
        throw InputError(path.string(), plain_message(e));
    }
}

std::string_view without_bom(std::string_view text) {
    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    return text.substr(0, kBom.size()) == kBom ? text.substr(kBom.size()) : text;
}

}  // namespace hmcr
