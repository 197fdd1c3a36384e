// SPDX-License-Identifier: Apache-2.0
#include "common/output_paths.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <map>
#include <optional>
#include <utility>

#include "common/error.h"
#include "common/file_names.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void cannot_write(const fs::path& path, const std::string& why) {
    throw InputError("cannot write " + path.string(), why);
}

std::atomic<std::uint64_t> g_identities{0};

// One spelling for one file: absolute, links resolved as far as the path exists.
fs::path identity(const fs::path& p) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::absolute(p).lexically_normal() : c;
}

// What tells two paths of one file apart from two files: its one spelling, and where it exists
// its device and inode (a hard link has a spelling of its own).
struct FileKey {
    fs::path spelling;
    std::optional<std::pair<dev_t, ino_t>> inode;
};

FileKey file_key(const fs::path& p) {
    g_identities.fetch_add(1, std::memory_order_relaxed);
    FileKey key{identity(p), std::nullopt};
    struct stat st {};
    if (::stat(p.c_str(), &st) == 0) key.inode = std::pair{st.st_dev, st.st_ino};
    return key;
}

// Paths by their keys: which one of those added a path names the same file as.
class FileKeys {
public:
    void add(const FileKey& key, std::size_t index) {
        m_spellings.emplace(key.spelling, index);
        if (key.inode) m_inodes.emplace(*key.inode, index);
    }
    std::optional<std::size_t> find(const FileKey& key) const {
        if (const auto it = m_spellings.find(key.spelling); it != m_spellings.end()) {
            return it->second;
        }
        if (!key.inode) return std::nullopt;
        if (const auto it = m_inodes.find(*key.inode); it != m_inodes.end()) return it->second;
        return std::nullopt;
    }

private:
    std::map<fs::path, std::size_t> m_spellings;  // the first of each spelling
    std::map<std::pair<dev_t, ino_t>, std::size_t> m_inodes;
};

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
    // Each path's key once, then look-ups: a study's thousands of outputs cost n log n, not n^2.
    FileKeys ins, outs;
    for (std::size_t i = 0; i < inputs.size(); ++i) ins.add(file_key(inputs[i]), i);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const FileKey key = file_key(outputs[i]);
        if (const auto in = ins.find(key)) {
            throw InputError(outputs[i].string(), "is an input of this command (" +
                                                      inputs[*in].string() +
                                                      "); refusing to write over it");
        }
        if (outs.find(key)) {
            throw InputError(outputs[i].string(), "is named for two outputs of this command");
        }
        outs.add(key, i);
    }
}

std::uint64_t file_identities_computed() { return g_identities.load(); }

void refuse_nested_dirs(const fs::path& output, const fs::path& input) {
    if (within(output, input) || within(input, output)) {
        throw InputError(output.string(),
                         "output folder is, holds or lies in the input folder " + input.string());
    }
}

}  // namespace hmcr
