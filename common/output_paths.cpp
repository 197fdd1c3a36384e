#include "common/output_paths.h"

#include <fmt/format.h>

#include <algorithm>
#include <climits>

#include "common/error.h"
#include "common/file_names.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void cannot_write(const fs::path& path, const std::string& why) {
    throw InputError("cannot write " + path.string(), why);
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

void check_output_file(const fs::path& file) {
    const std::size_t name = file.filename().native().size();
    if (name == 0 || file.filename() == "." || file.filename() == "..") {
        cannot_write(file, "it names a folder, not a file");
    }
    if (name > kMaxFileNameBytes) {
        cannot_write(
            file, fmt::format("its name is {} bytes long, more than {}", name, kMaxFileNameBytes));
    }
    if (file.native().size() >= PATH_MAX) {
        cannot_write(file, fmt::format("its path is longer than {} bytes", PATH_MAX - 1));
    }
    std::error_code ec;
    if (fs::is_directory(file, ec)) cannot_write(file, "it is a folder");
    if (fs::exists(file, ec) && !fs::is_regular_file(file, ec)) {
        cannot_write(file, "it is not a regular file");
    }
}

void check_output_folder(const fs::path& folder) {
    if (folder.native().size() >= PATH_MAX) {
        cannot_write(folder, fmt::format("its path is longer than {} bytes", PATH_MAX - 1));
    }
    std::error_code ec;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
        cannot_write(folder, "it is not a folder");
    }
}

void refuse_overwriting(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        for (const fs::path& in : inputs) {
            if (same_file(outputs[i], in)) {
                throw InputError(
                    outputs[i].string(),
                    "is an input of this command (" + in.string() + "); refusing to write over it");
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
        throw InputError(output.string(),
                         "output folder is, holds or lies in the input folder " + input.string());
    }
}

}  // namespace hmcr
