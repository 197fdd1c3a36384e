// SPDX-License-Identifier: Apache-2.0
// One MGF file as statements: lines joined at an escaped newline, split into words, comments
// and blank lines dropped, and every `xf` that opens a transformation paired with the `xf`
// that closes it (the specification requires them to balance within a file).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hmcr {

struct MgfStatement {
    int line = 0;                    // the first line of the statement
    std::vector<std::string> words;  // words[0] is the entity
};

struct MgfFile {
    std::filesystem::path path;
    std::uint32_t index = 0;  // in the polygon soup's files
    std::vector<MgfStatement> statements;
    std::vector<std::size_t> xf_close;  // for an opening xf, its closing statement's index
};

// Reads and splits the file. Throws InputError "path:line: why" for a NUL byte, an xf that is
// never closed, or one that closes nothing.
MgfFile read_mgf_file(const std::filesystem::path& path, std::uint32_t index);

// Files include each other at most this deep.
inline constexpr std::size_t kMaxMgfIncludeDepth = 64;

// Throws InputError at `where` when `next`, included from the innermost of the files `open`,
// would nest includes more than kMaxMgfIncludeDepth deep or is one of them (a cycle).
void check_mgf_include(const std::vector<std::filesystem::path>& open,
                       const std::filesystem::path& next, const std::string& where);

}  // namespace hmcr
