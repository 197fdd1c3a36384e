// SPDX-License-Identifier: Apache-2.0
#include "common/text_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <string_view>
#include <vector>

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
    return out.substr(0, token) +
           "last read: " + quote(std::string_view(out).substr(token + kLastRead.size()));
}

// The text as nlohmann's parser reads it, one character at a time, telling how far it has read:
// the position of a key, for its line.
class ReadHead {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    ReadHead(const char* at, const char** head) : m_at(at), m_head(head) {}
    reference operator*() const { return *m_at; }
    ReadHead& operator++() {
        *m_head = ++m_at;
        return *this;
    }
    bool operator==(const ReadHead& other) const { return m_at == other.m_at; }
    bool operator!=(const ReadHead& other) const { return m_at != other.m_at; }

private:
    const char* m_at;
    const char** m_head;
};

// Parses the text, refusing a key given twice in one object (nlohmann would keep the last, and a
// typo'd copy of a setting would silently win): "PATH:LINE: key 'k' is given twice in one
// object (first at line L)".
nlohmann::json parse_without_duplicate_keys(const std::string& text, const fs::path& path) {
    const char* head = text.data();
    const char* counted = text.data();
    int line = 1;                                     // of `counted`
    std::vector<std::map<std::string, int>> objects;  // the keys of each open object, and lines
    const auto callback = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (event == Event::object_start) {
            objects.emplace_back();
        } else if (event == Event::object_end) {
            objects.pop_back();
        } else if (event == Event::key) {
            line += int(std::count(counted, head, '\n'));  // the key ends just before the head
            counted = head;
            const auto [it, fresh] = objects.back().emplace(parsed.get<std::string>(), line);
            if (!fresh) {
                throw InputError(
                    at(path, line),
                    fmt::format("key {} is given twice in one object (first at line {})",
                                quote(it->first), it->second));
            }
        }
        return true;
    };
    return nlohmann::json::parse(ReadHead(text.data(), &head),
                                 ReadHead(text.data() + text.size(), &head), callback);
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
            throw InputError(path.string(), "grew past the limit of " + std::to_string(max_bytes) +
                                                " bytes while read");
        }
    }
    if (in.bad()) throw InputError(path.string(), "cannot be read");
    return text;
}

nlohmann::json read_json_file(const fs::path& path) {
    constexpr std::uint64_t kMaxJsonBytes = std::uint64_t(256) << 20;
    const std::string text = read_text_file(path, kMaxJsonBytes);
    try {
        return parse_without_duplicate_keys(text, path);
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
