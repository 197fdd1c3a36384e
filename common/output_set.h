// SPDX-License-Identifier: Apache-2.0
// A command's output files, written as one set (docs/design.md §5.7). Made before any work, it
// checks every file (output_paths.h), creates the folders they go into, locks the outputs
// (output_lock.h) and proves each folder writable by making and removing a temporary file
// there (durable_file.h). At the end the command writes each file's temporary file (temp(): any
// writer of atomic_file.h replaces it) and commit() flushes them, renames them all into place
// and flushes their folders. A failure or a signal before commit() leaves none of the set: the
// destructor removes the temporary files, the locks and the folders it created.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include "common/output_lock.h"

namespace hmcr {

class OutputSet {
public:
    // `files`: the set. `folder`: the output folder that holds them all, locked as one (a
    // reference, a study); empty: each file is locked (a solve's FILE.vtp, .json and .pvsm).
    // Throws InputError "cannot write PATH: why" for the first file or folder that fails.
    explicit OutputSet(std::vector<std::filesystem::path> files,
                       const std::filesystem::path& folder = {});
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    // Where `file` (one of the set, spelled as given) is to be written before commit(): a
    // temporary file beside it, made at the first call.
    const std::filesystem::path& temp(const std::filesystem::path& file);
    // Every file into place, durably; then the locks are released. Throws InputError "cannot
    // write FILE: why" when a flush or a rename fails.
    void commit();

private:
    void lock(const std::filesystem::path& output, bool is_folder);
    void abandon() noexcept;

    std::vector<std::filesystem::path> m_files, m_temps;   // a temp is empty until temp()
    std::map<std::filesystem::path, std::size_t> m_index;  // of m_files: temp() of thousands
    std::vector<std::filesystem::path> m_made_folders;     // outermost first
    std::vector<std::unique_ptr<OutputLock>> m_locks;
    bool m_committed = false;
};

// Files written as one batch without an OutputSet's checks and locks: the files of one study
// cell, in the study's locked folder, checked before its first cell. temp() makes a temporary
// file beside a file (and the file's folder, if missing); commit() flushes them, renames them
// all into place and flushes their folders. A batch not committed (a failure, a signal) leaves
// none of its files: the destructor removes the temporary files and the folders it made, if
// they hold nothing else.
class FileBatch {
public:
    FileBatch() = default;
    ~FileBatch();
    FileBatch(const FileBatch&) = delete;
    FileBatch& operator=(const FileBatch&) = delete;

    // Where `file` is to be written before commit() (the same temporary file at every call).
    // Throws InputError "cannot write FILE: why".
    std::filesystem::path temp(const std::filesystem::path& file);
    // Throws InputError "cannot write FILE: why" when a flush or a rename fails.
    void commit();

private:
    std::vector<std::filesystem::path> m_files, m_temps;
    std::vector<std::filesystem::path> m_made_folders;  // outermost first
    bool m_committed = false;
};

// Proves that a file can be made in `file`'s folder, when the folder exists, by making and
// removing a temporary file there (a folder not made yet is made when the file is written).
// Throws InputError "cannot write FILE: why": a read-only folder, or a file in the folder's
// place. A study checks its cells' folders so, before its first cell.
void check_folder_takes(const std::filesystem::path& file);

}  // namespace hmcr
