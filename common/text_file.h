// SPDX-License-Identifier: Apache-2.0
// Reading the files a user hands hmcr (scenes, meshes, materials, reference and study files):
// one reader, so that every error names the file, and the line where there is one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "common/error.h"

namespace hmcr {

// Larger text files are refused before anything is read: a mesh of 10^7 patches is a few
// hundred MB of OBJ, and a special file such as /dev/zero must not be read until memory ends.
inline constexpr std::uint64_t kMaxTextBytes = std::uint64_t(4) << 30;

// The whole file. Throws InputError "PATH: why" when it does not exist, is not a regular file
// (a directory, a FIFO, a device; symbolic links are followed), is larger than max_bytes or
// cannot be read.
std::string read_text_file(const std::filesystem::path& path,
                           std::uint64_t max_bytes = kMaxTextBytes);

// The text after a UTF-8 byte-order mark, if it starts with one (editors on Windows write it).
std::string_view without_bom(std::string_view text);

// The parsed JSON file; a syntax error, or a key given twice in one object, is "PATH:LINE: why".
nlohmann::json read_json_file(const std::filesystem::path& path);

// Runs `read` on the parsed file; a missing key, a wrong type, or an InputError of `read`
// becomes a one-line error naming the file.
template <typename Read>
auto read_json_file(const std::filesystem::path& path, Read&& read) {
    const nlohmann::json j = read_json_file(path);
    try {
        return read(j);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path.string(), e.what());
    } catch (const InputError& e) {
        throw InputError(path.string(), e.what());
    }
}

}  // namespace hmcr
