// SPDX-License-Identifier: Apache-2.0
// A lock on an output (docs/design.md §5.7), held by one hmcr run from the check of its outputs
// to their last rename, so that two runs given the same output cannot mix their files: the
// second is refused at once. The lock is a file locked with flock(2), which a shared file
// system (NFS) passes on to its server, and removed when the lock is released. A run killed
// outright leaves the file but not the lock (the kernel releases it with the process): the
// next run takes it over. Outputs nest: a run locks its own output first, then looks for the
// locks of other runs in the folders around it and, for a folder, in it; of two runs starting
// at once on nested outputs, one at least sees the other's lock.
#pragma once

#include <filesystem>

namespace hmcr {

// The lock file of an output: ".NAME.lock" beside a file, "DIR/.hmcr.lock" in a folder.
std::filesystem::path lock_file_of(const std::filesystem::path& output, bool is_folder);

class OutputLock {
public:
    // Locks `output` (whose folder must exist). Throws InputError "cannot write OUTPUT: another
    // hmcr run is writing it (...)" while another run holds it, or holds a folder around it, or
    // (for a folder) anything in it: a run on ref/x.vtp and one on the folder ref exclude each
    // other too. "cannot write OUTPUT: why" when the lock file cannot be made. Where the file
    // system has no locks, the run goes on unlocked.
    OutputLock(const std::filesystem::path& output, bool is_folder);
    ~OutputLock();  // removes the lock file, then releases the lock
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

private:
    void release() noexcept;

    std::filesystem::path m_file;
    int m_fd = -1;
};

}  // namespace hmcr
