// Atomic file output (docs/design.md §5): write a temp file beside the target, then rename it into
// place, so readers see the old file or the complete new one and a failed run leaves nothing.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace hmcr {

// Creates the target's parent directory if needed, creates a fresh temp file in that directory,
// calls `write` with its path and renames the result onto `target`. On any exception the temp
// file is removed and the exception rethrown. A folder or temp file that cannot be made, or a
// rename that fails, is an InputError "cannot write TARGET: why" (the user's disk, rights or
// path).
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& write);

// write_file_atomically with the given bytes.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

}  // namespace hmcr
