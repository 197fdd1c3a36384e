#include "common/error.h"

namespace hmcr {

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
