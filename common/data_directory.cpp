// SPDX-License-Identifier: Apache-2.0
#include "common/data_directory.h"

#include <cstdlib>
#include <string>
#include <system_error>

// The build defines both for this file alone (CMakeLists.txt); without them no source tree is
// known, and only an install or $HMCR_DATA_DIR is found.
#ifndef HMCR_SOURCE_DIR
#define HMCR_SOURCE_DIR ""
#endif
#ifndef HMCR_BUILD_DIR
#define HMCR_BUILD_DIR ""
#endif

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// Whether `path` is `folder` or lies below it (both absolute and normal).
bool lies_in(const fs::path& path, const fs::path& folder) {
    const fs::path relative = path.lexically_relative(folder);
    return !folder.empty() && !relative.empty() && *relative.begin() != "..";
}

}  // namespace

fs::path data_directory() {
    const char* env = std::getenv(kDataDirVariable);
    if (env != nullptr && *env != '\0') return env;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    fs::path installed = (exe.parent_path() / ".." / "share" / "hmcr").lexically_normal();
    if (!ec && fs::is_directory(installed, ec)) return installed;
    const fs::path build = fs::weakly_canonical(HMCR_BUILD_DIR, ec);
    if (!exe.empty() && lies_in(exe, build)) return HMCR_SOURCE_DIR;
    return installed;
}

}  // namespace hmcr
