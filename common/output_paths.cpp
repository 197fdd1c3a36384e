#include "common/output_paths.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <algorithm>

#include "common/error.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void cannot_write(const fs::path& path, const std::string& why) {
    throw InputError("cannot write " + path.string(), why);
}

void require_writable_dir(const fs::path& dir, const fs::path& target) {
    std::error_code ec;
    const fs::path d = dir.empty() ? fs::path(".") : dir;
    fs::create_directories(d, ec);
    if (!fs::is_directory(d, ec)) {
        cannot_write(target, (ec ? ec.message() : "not a folder") + ": " + d.string());
    }
    // A file made and removed: the one test that also holds for root, /proc and full quotas.
    const fs::path probe = d / (".hmcr-probe-" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) cannot_write(target, std::strerror(errno));
    ::close(fd);
    fs::remove(probe, ec);
}

// One spelling for one file: absolute, links resolved as far as the path exists.
fs::path identity(const fs::path& p) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::absolute(p).lexically_normal() : c;
}

bool same_file(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true;
    return identity(a) == identity(b);
}

bool within(const fs::path& inner, const fs::path& outer) {
    const fs::path i = identity(inner), o = identity(outer);
    auto [oi, ii] = std::mismatch(o.begin(), o.end(), i.begin(), i.end());
    return oi == o.end();
}

}  // namespace

void prepare_output_file(const fs::path& file) {
    std::error_code ec;
    if (fs::is_directory(file, ec)) cannot_write(file, "it is a folder");
    if (fs::exists(file, ec) && !fs::is_regular_file(file, ec)) {
        cannot_write(file, "it is not a regular file");
    }
    require_writable_dir(file.parent_path(), file);
}

void prepare_output_dir(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) cannot_write(dir, "it is not a folder");
    require_writable_dir(dir, dir);
}

void refuse_overwriting(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        for (const fs::path& in : inputs) {
            if (same_file(outputs[i], in)) {
                throw InputError(outputs[i].string(), "is an input of this command (" +
                                                          in.string() + "); refusing to write over it");
            }
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (same_file(outputs[i], outputs[j])) {
                throw InputError(outputs[i].string(), "is named for two outputs of this command");
            }
        }
    }
}

void refuse_nested_dirs(const fs::path& output, const fs::path& input) {
    if (within(output, input) || within(input, output)) {
        throw InputError(output.string(), "output folder is, holds or lies in the input folder " +
                                              input.string());
    }
}

}  // namespace hmcr
