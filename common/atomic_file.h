// SPDX-License-Identifier: Apache-2.0
// Atomic, durable file output (docs/design.md §5.7): write a temporary file beside the target,
// flush it to the disk, rename it into place and flush the folder. Readers see the old file or
// the complete new one; a failed run leaves nothing; after a crash of the machine the target is
// the old file or the complete new one, never an empty or partial one.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace hmcr {

// Creates the target's parent directory if needed, creates a fresh temp file in that directory
// (durable_file.h: a name no other writer picks), calls `write` with its path, flushes it,
// renames it onto `target` and flushes the folder. On any exception the temp file is removed
// and the exception rethrown. A folder or temp file that cannot be made, a flush or a rename
// that fails, is an InputError "cannot write TARGET: why" (the user's disk, rights or path).
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& write);

// write_file_atomically with the given bytes.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

}  // namespace hmcr
