// SPDX-License-Identifier: Apache-2.0
#include "common/output_set.h"

#include <set>
#include <stdexcept>

#include "common/durable_file.h"
#include "common/error.h"
#include "common/output_paths.h"

namespace hmcr {

namespace fs = std::filesystem;

namespace {

// Each file's temporary file flushed, then renamed onto it (each temp cleared once renamed),
// then their folders flushed.
void commit_temps(const std::vector<fs::path>& files, std::vector<fs::path>& temps) {
    for (std::size_t i = 0; i < files.size(); ++i) sync_file(temps[i], files[i]);
    std::set<fs::path> folders;
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::error_code ec;
        fs::rename(temps[i], files[i], ec);
        if (ec) throw InputError("cannot write " + files[i].string(), ec.message());
        temps[i].clear();
        folders.insert(files[i].parent_path());
    }
    for (const fs::path& f : folders) sync_folder(f, files.front());
}

// The temporary files not renamed, then the folders made (innermost first), where empty.
void remove_made(const std::vector<fs::path>& temps, const std::vector<fs::path>& folders) {
    std::error_code ignored;
    for (const fs::path& tmp : temps) {
        if (!tmp.empty()) fs::remove(tmp, ignored);
    }
    for (auto it = folders.rbegin(); it != folders.rend(); ++it) fs::remove(*it, ignored);
}

// Each missing level of `folder`, made and added to `made`, so that a failure can take it back;
// a file in the way fails the `output` that needs the folder.
void make_folders(const fs::path& folder, const fs::path& output, std::vector<fs::path>& made) {
    if (folder.empty()) return;
    std::error_code ec;
    if (fs::is_directory(folder, ec)) return;
    make_folders(folder.parent_path(), output, made);
    if (fs::create_directory(folder, ec)) {
        made.push_back(folder);
    } else if (std::error_code again; !fs::is_directory(folder, again)) {  // not another run's
        const std::string why = fs::exists(folder, again) ? "not a folder" : ec.message();
        throw InputError("cannot write " + output.string(), why + ": " + folder.string());
    }
}

}  // namespace

OutputSet::OutputSet(std::vector<fs::path> files, const fs::path& folder)
    : m_files(std::move(files)) {
    try {
        for (const fs::path& file : m_files) check_output_file(file);
        if (!folder.empty()) {
            check_output_folder(folder);
            make_folders(folder, folder, m_made_folders);
            lock(folder, true);
        }
        for (const fs::path& file : m_files) {
            make_folders(file.parent_path(), file, m_made_folders);
            if (folder.empty()) lock(file, false);
            std::error_code ignored;
            fs::remove(create_temp_beside(file), ignored);  // the folder takes files
        }
        m_temps.resize(m_files.size());
        for (std::size_t i = 0; i < m_files.size(); ++i) m_index.emplace(m_files[i], i);
    } catch (...) {
        abandon();
        throw;
    }
}

OutputSet::~OutputSet() {
    if (!m_committed) abandon();
}

const fs::path& OutputSet::temp(const fs::path& file) {
    const auto it = m_index.find(file);
    if (it == m_index.end()) {
        throw std::logic_error(file.string() + " is not an output of this command");
    }
    fs::path& tmp = m_temps[it->second];
    if (tmp.empty()) tmp = create_temp_beside(file);
    return tmp;
}

void OutputSet::commit() {
    for (std::size_t i = 0; i < m_files.size(); ++i) {
        if (m_temps[i].empty()) throw std::logic_error(m_files[i].string() + " was not written");
    }
    commit_temps(m_files, m_temps);
    m_committed = true;
    m_locks.clear();
}

void OutputSet::lock(const fs::path& output, bool is_folder) {
    m_locks.push_back(std::make_unique<OutputLock>(output, is_folder));
}

void check_folder_takes(const fs::path& file) {
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    std::error_code ec;
    const fs::file_status status = fs::status(folder, ec);
    if (status.type() == fs::file_type::not_found) return;
    if (!fs::is_directory(status)) {
        throw InputError("cannot write " + file.string(), "not a folder: " + folder.string());
    }
    fs::remove(create_temp_beside(file), ec);
}

void OutputSet::abandon() noexcept {
    // The locks go before the folders; a folder that holds anything now (a study's finished
    // cells) stays.
    remove_made(m_temps, {});
    m_locks.clear();
    remove_made({}, m_made_folders);
}

FileBatch::~FileBatch() {
    if (!m_committed) remove_made(m_temps, m_made_folders);
}

fs::path FileBatch::temp(const fs::path& file) {
    for (std::size_t i = 0; i < m_files.size(); ++i) {
        if (m_files[i] == file) return m_temps[i];
    }
    make_folders(file.parent_path(), file, m_made_folders);
    m_temps.push_back(create_temp_beside(file));
    m_files.push_back(file);
    return m_temps.back();
}

void FileBatch::commit() {
    if (!m_files.empty()) commit_temps(m_files, m_temps);
    m_committed = true;
}

}  // namespace hmcr
