// SPDX-License-Identifier: Apache-2.0
#include "common/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <utility>

#include "common/error.h"
#include "common/file_names.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void lock_failed(const fs::path& output, const std::string& why) {
    throw InputError("cannot write " + output.string(), why);
}

// The file at `path` is the one open as `fd`: nobody removed it (and released it) between our
// open and our lock.
bool still_there(int fd, const fs::path& path) {
    struct stat open_file {
    }, named{};
    return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 &&
           open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

// The lock files this process holds, by device and inode: a probe of one of them is no other
// run (a flock of the same file through another descriptor would conflict with our own).
class HeldLocks {
public:
    void add(int fd) {
        with(fd, [this](const Key& k) { m_keys.insert(k); });
    }
    void remove(int fd) {
        with(fd, [this](const Key& k) { m_keys.erase(k); });
    }
    bool has(int fd) {
        bool found = false;
        with(fd, [&](const Key& k) { found = m_keys.count(k) > 0; });
        return found;
    }

private:
    using Key = std::pair<dev_t, ino_t>;
    template <class F>
    void with(int fd, F&& f) {
        struct stat st {};
        if (::fstat(fd, &st) != 0) return;
        const std::lock_guard lock(m_mutex);
        f(Key{st.st_dev, st.st_ino});
    }
    std::mutex m_mutex;
    std::set<Key> m_keys;
};

HeldLocks& held_locks() {
    static HeldLocks locks;
    return locks;
}

// Whether another run holds the lock file at `lock` (no such file: nobody). The probe takes a
// shared lock for an instant, which fails while a run holds its exclusive one.
bool held_by_another_run(const fs::path& lock) {
    const int fd = ::open(lock.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) return false;
    struct stat st {};
    bool held = false;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && !held_locks().has(fd)) {
        held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    }
    ::close(fd);  // releases the probe's lock
    return held;
}

bool is_lock_name(const std::string& name) {
    return name.size() > 6 && name.front() == '.' && name.ends_with(".lock");
}

// Runs on nested outputs (docs/design.md §5.7): a folder being written by another run around
// `output` (its .hmcr.lock in any folder above), or, for an output folder, another run's lock
// on anything in it (a file's, or a folder's below).
void refuse_locked_around(const fs::path& output, bool is_folder) {
    std::error_code ec;
    const fs::path full = fs::weakly_canonical(fs::absolute(output, ec), ec);
    if (ec) return;
    for (fs::path folder = full.parent_path();; folder = folder.parent_path()) {
        const fs::path lock = folder / ".hmcr.lock";
        if (held_by_another_run(lock)) {
            lock_failed(output, "another hmcr run is writing the folder " + folder.string() +
                                    " (its lock is " + lock.string() +
                                    "; wait for that run to end)");
        }
        if (folder == folder.parent_path()) break;
    }
    if (!is_folder) return;
    for (fs::recursive_directory_iterator
             it(full, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec)) {
        const fs::path& path = it->path();
        if (is_lock_name(path.filename().string()) && held_by_another_run(path)) {
            lock_failed(output, "another hmcr run is writing in it (its lock is " + path.string() +
                                    "; wait for that run to end)");
        }
    }
}

}  // namespace

fs::path lock_file_of(const fs::path& output, bool is_folder) {
    if (is_folder) return output / ".hmcr.lock";
    constexpr std::size_t kRoom = kMaxFileNameBytes - (sizeof "..lock" - 1);
    std::string name = ".";
    name += output.filename().string().substr(0, kRoom);
    return output.parent_path() / (name + ".lock");
}

OutputLock::OutputLock(const fs::path& output, bool is_folder)
    : m_file(lock_file_of(output, is_folder)) {
    for (int attempt = 0;; ++attempt) {
        m_fd = ::open(m_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
        if (m_fd < 0) lock_failed(output, std::strerror(errno));
        if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
            const int error = errno;
            if (error != EWOULDBLOCK) return;  // no locks on this file system: go on unlocked
            ::close(m_fd);
            m_fd = -1;
            lock_failed(output, "another hmcr run is writing it (its lock is " + m_file.string() +
                                    "; wait for that run to end)");
        }
        if (still_there(m_fd, m_file)) break;
        ::close(m_fd);  // the holder released and removed it as we opened it: again
        m_fd = -1;
        if (attempt == 100) lock_failed(output, "its lock " + m_file.string() + " keeps changing");
    }
    // Ours now; then the runs around it, each of which, locked first, sees ours in turn.
    held_locks().add(m_fd);
    try {
        refuse_locked_around(output, is_folder);
    } catch (...) {
        release();
        throw;
    }
}

OutputLock::~OutputLock() { release(); }

void OutputLock::release() noexcept {
    if (m_fd < 0) return;
    held_locks().remove(m_fd);
    ::unlink(m_file.c_str());
    ::close(m_fd);
    m_fd = -1;
}

}  // namespace hmcr
