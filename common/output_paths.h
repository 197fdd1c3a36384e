// SPDX-License-Identifier: Apache-2.0
// Checks on where a command will write, made before any work: a run that would fail to write,
// or write over one of its own inputs, is refused at once with one line, losing nothing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace hmcr {

// Checks, without touching the disk, that a file can be put at `file`: it names a file, of at
// most 255 bytes (a path of at most 4095), and is neither a folder nor a device, FIFO or
// socket. Throws InputError "cannot write PATH: why". (output_set.h then makes its folder and
// proves it writable.)
void check_output_file(const std::filesystem::path& file);
// The same for an output folder: an existing file of that name is an error.
void check_output_folder(const std::filesystem::path& folder);

// Throws InputError when an output is one of the inputs or another output (the same file by any
// path, link or hard link). Each path's identity (its spelling with links resolved, its inode)
// is found once, and compared by look-ups: n log n for n paths.
void refuse_overwriting(const std::vector<std::filesystem::path>& outputs,
                        const std::vector<std::filesystem::path>& inputs);
// The identities refuse_overwriting has found in this process: the count of its work, for a
// test that it is one per path.
std::uint64_t file_identities_computed();
// Throws InputError when the output folder is, holds or lies in the input folder.
void refuse_nested_dirs(const std::filesystem::path& output, const std::filesystem::path& input);

}  // namespace hmcr
