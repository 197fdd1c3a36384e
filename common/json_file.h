// Reading a JSON file whose errors name the file (a reference summary, a study cell).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace hmcr {

// The parsed file; throws std::invalid_argument "PATH: why" when it cannot be read or parsed.
nlohmann::json read_json_file(const std::filesystem::path& path);

// Runs `read` on the parsed file; a missing key or a wrong type becomes the same one-line
// error naming the file.
template <typename Read>
auto read_json_file(const std::filesystem::path& path, Read&& read) {
    const nlohmann::json j = read_json_file(path);
    try {
        return read(j);
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(path.string() + ": " + e.what());
    }
}

}  // namespace hmcr
