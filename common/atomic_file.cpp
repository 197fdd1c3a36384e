#include "common/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <stdexcept>

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
    if (!parent.empty()) std::filesystem::create_directories(parent);
    const std::filesystem::path tmp = temp_path_for(target);
    try {
        write(tmp);
        std::filesystem::rename(tmp, target);
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
        if (!out) throw std::runtime_error("cannot write " + target.string());
    });
}

}  // namespace hmcr
