// SPDX-License-Identifier: Apache-2.0
#include "common/error.h"

#include <fmt/format.h>

namespace hmcr {

std::string one_line(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u != 0x7f) {
            out.push_back(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            out += fmt::format("\\x{:02x}", u);
        }
    }
    return out;
}

std::string shorten_place(std::string_view where) {
    constexpr std::size_t kMax = 300, kHead = 100;
    if (where.size() <= kMax) return std::string(where);
    return std::string(where.substr(0, kHead)) + "..." +
           std::string(where.substr(where.size() - (kMax - kHead)));
}

std::string at(const std::filesystem::path& path, int line) {
    return path.string() + ":" + std::to_string(line);
}

std::string quote(std::string_view token) {
    constexpr std::size_t kMax = 40;
    std::string out(1, '\'');
    out.append(token.substr(0, kMax));
    if (token.size() > kMax) out.append("...");
    out.push_back('\'');
    return out;
}

}  // namespace hmcr
