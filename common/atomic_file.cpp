// SPDX-License-Identifier: Apache-2.0
#include "common/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/durable_file.h"
#include "common/error.h"

namespace hmcr {

void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& write) {
    const std::filesystem::path parent = target.parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec) throw InputError("cannot write " + target.string(), ec.message());
    // Creating the temp file ourselves names the reason (permission, no such folder, a /proc
    // that takes no files) in our words; the writer then fills it.
    const std::filesystem::path tmp = create_temp_beside(target);
    try {
        write(tmp);
        sync_file(tmp, target);
        std::filesystem::rename(tmp, target, ec);
        if (ec) throw InputError("cannot write " + target.string(), ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
    sync_folder(parent, target);
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
