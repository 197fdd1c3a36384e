#include "common/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <atomic>
#include <fstream>
#include <stdexcept>

#include "common/error.h"

namespace hmcr {
namespace {

// Unique per process and call, so concurrent writers (threads or runs) never share a temp file.
std::filesystem::path temp_path_for(const std::filesystem::path& target) {
    static std::atomic<unsigned long> counter{0};
    std::filesystem::path tmp = target;
    tmp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    return tmp;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& write) {
    const std::filesystem::path parent = target.parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) throw InputError("cannot write " + target.string(), ec.message());
    const std::filesystem::path tmp = temp_path_for(target);
    // Creating the temp file ourselves names the reason (permission, no such folder, a /proc
    // that takes no files) in our words; the writer then fills it.
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) throw InputError("cannot write " + target.string(), std::strerror(errno));
    ::close(fd);
    try {
        write(tmp);
        std::filesystem::rename(tmp, target, ec);
        if (ec) throw InputError("cannot write " + target.string(), ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

void write_text_atomically(const std::filesystem::path& target, const std::string& text) {
    write_file_atomically(target, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) throw InputError("cannot write " + target.string(), std::strerror(errno));
    });
}

}  // namespace hmcr
