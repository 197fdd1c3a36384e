#include "common/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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
        if (still_there(m_fd, m_file)) return;
        ::close(m_fd);  // the holder released and removed it as we opened it: again
        m_fd = -1;
        if (attempt == 100) lock_failed(output, "its lock " + m_file.string() + " keeps changing");
    }
}

OutputLock::~OutputLock() {
    if (m_fd < 0) return;
    ::unlink(m_file.c_str());
    ::close(m_fd);
}

}  // namespace hmcr
