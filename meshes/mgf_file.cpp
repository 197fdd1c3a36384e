// SPDX-License-Identifier: Apache-2.0
#include "meshes/mgf_file.h"

#include <fmt/format.h>

#include "common/error.h"
#include "common/text_file.h"
#include "meshes/obj_lines.h"

namespace hmcr {
namespace {

// Joins escaped newlines and keeps the statements that are not comments.
std::vector<MgfStatement> split_statements(std::string_view text, const std::string& path) {
    std::vector<MgfStatement> out;
    std::string pending;
    int first_line = 0;
    for_each_line(without_bom(text), [&](int number, std::string_view line) {
        if (line.find('\0') != std::string_view::npos) {
            throw InputError(at(path, number), "binary data (NUL byte) in a text file");
        }
        if (pending.empty()) first_line = number;
        const bool continued = !line.empty() && line.back() == '\\';
        pending.append(continued ? line.substr(0, line.size() - 1) : line).push_back(' ');
        if (continued) return;
        MgfStatement s{first_line, {}};
        for (std::string_view w : split_tokens(pending)) s.words.emplace_back(w);
        pending.clear();
        if (!s.words.empty() && s.words[0][0] != '#') out.push_back(std::move(s));
    });
    if (!pending.empty()) {
        MgfStatement s{first_line, {}};
        for (std::string_view w : split_tokens(pending)) s.words.emplace_back(w);
        if (!s.words.empty() && s.words[0][0] != '#') out.push_back(std::move(s));
    }
    return out;
}

std::vector<std::size_t> pair_transforms(const std::vector<MgfStatement>& statements,
                                         const std::string& path) {
    std::vector<std::size_t> close(statements.size(), 0), open;
    for (std::size_t i = 0; i < statements.size(); ++i) {
        if (statements[i].words[0] != "xf") continue;
        if (statements[i].words.size() > 1) {
            open.push_back(i);
        } else if (open.empty()) {
            throw InputError(at(path, statements[i].line), "xf ends no transformation");
        } else {
            close[open.back()] = i;
            open.pop_back();
        }
    }
    if (!open.empty()) {
        throw InputError(at(path, statements[open.back()].line),
                         "xf is never ended in this file (an xf without arguments ends it)");
    }
    return close;
}

}  // namespace

void check_mgf_include(const std::vector<std::filesystem::path>& open,
                       const std::filesystem::path& next, const std::string& where) {
    if (open.size() >= kMaxMgfIncludeDepth) {
        throw InputError(where,
                         fmt::format("includes nested more than {} deep", kMaxMgfIncludeDepth));
    }
    for (const std::filesystem::path& file : open) {
        if (file == next) throw InputError(where, "the file includes itself");
    }
}

MgfFile read_mgf_file(const std::filesystem::path& path, std::uint32_t index) {
    MgfFile file{path, index, split_statements(read_text_file(path), path.string()), {}};
    file.xf_close = pair_transforms(file.statements, path.string());
    return file;
}

}  // namespace hmcr
