// SPDX-License-Identifier: Apache-2.0
#include "common/durable_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "common/error.h"
#include "common/file_names.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

std::atomic<SyncCall> g_sync{&::fsync};

[[noreturn]] void write_failed(const fs::path& target, int error) {
    throw InputError("cannot write " + target.string(), std::strerror(error));
}

// 13 characters of [a-z0-5] from 64 random bits: the names of two writers, on one machine or
// many, differ but once in 2^64 (and O_EXCL settles even that).
std::string random_suffix() {
    std::uint64_t bits = 0;
    if (::getrandom(&bits, sizeof bits, 0) != ssize_t(sizeof bits)) {
        bits = std::uint64_t(::getpid()) * 0x9e3779b97f4a7c15ull ^
               std::uint64_t(reinterpret_cast<std::uintptr_t>(&bits));
    }
    static constexpr char kDigits[] = "abcdefghijklmnopqrstuvwxyz012345";
    std::string out;
    for (int i = 0; i < 13; ++i, bits >>= 5) out.push_back(kDigits[bits & 31]);
    return out;
}

// ".NAME.tmp.": the target's name cut so that the whole name, with the 13 random characters,
// stays within kMaxFileNameBytes.
std::string temp_prefix(const fs::path& target) {
    constexpr std::size_t kRoom = kMaxFileNameBytes - (sizeof "..tmp." - 1) - 13;
    std::string name = ".";
    name += target.filename().string().substr(0, kRoom);
    return name + ".tmp.";
}

// Opens `path` for flushing (read-only is enough for fsync) and flushes it.
void sync(const fs::path& path, int flags, const fs::path& target) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
    if (fd < 0) write_failed(target, errno);
    const int result = g_sync.load()(fd);
    const int error = errno;
    ::close(fd);
    if (result != 0 && error != EINVAL) write_failed(target, error);
}

}  // namespace

fs::path create_temp_beside(const fs::path& target) {
    const fs::path folder = target.parent_path();
    for (int attempt = 0;; ++attempt) {
        fs::path tmp = folder / (temp_prefix(target) + random_suffix());
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return tmp;
        }
        if (errno != EEXIST || attempt == 8) write_failed(target, errno);
    }
}

void sync_file(const fs::path& file, const fs::path& target) { sync(file, 0, target); }

void sync_folder(const fs::path& folder, const fs::path& target) {
    sync(folder.empty() ? fs::path(".") : folder, O_DIRECTORY, target);
}

SyncCall replace_sync_call(SyncCall call) { return g_sync.exchange(call); }

}  // namespace hmcr
