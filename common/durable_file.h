// SPDX-License-Identifier: Apache-2.0
// The steps of durable file output (docs/design.md §5.7), for atomic_file.h and output_set.h:
// a temporary file under a name no other writer can pick, and the flushes that make a rename
// survive a crash of the machine (the file's bytes before the rename, its folder's entry after).
#pragma once

#include <filesystem>

namespace hmcr {

// Creates an empty file in `target`'s folder, named after the target with a random suffix
// (".NAME.tmp.RANDOM", at most 255 bytes), exclusively (O_EXCL): no other thread, process, or
// rank on another node of a shared file system gets the same file. Returns its path. Throws
// InputError "cannot write TARGET: why" (no such folder, no rights, a full disk).
std::filesystem::path create_temp_beside(const std::filesystem::path& target);

// Flushes the file's bytes to the disk. Throws InputError "cannot write TARGET: why" (the disk
// failed or is full); a file system that does not flush (EINVAL) is taken as it is.
void sync_file(const std::filesystem::path& file, const std::filesystem::path& target);
// Flushes a folder's entries (the names renamed or created in it) to the disk, where the file
// system can; a folder that cannot be opened or flushed is an InputError naming `target`.
void sync_folder(const std::filesystem::path& folder, const std::filesystem::path& target);

// The system call behind both flushes, fsync(2). A test replaces it to see which files are
// flushed, and when; returns the call it replaces.
using SyncCall = int (*)(int fd);
SyncCall replace_sync_call(SyncCall call);

}  // namespace hmcr
