// SPDX-License-Identifier: Apache-2.0
#include "common/file_names.h"

#include <fmt/format.h>

#include "common/error.h"

namespace hmcr {
namespace {

bool portable(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
           c == '_' || c == '-' || c == '+';
}

}  // namespace

std::optional<std::string> name_problem(std::string_view name) {
    if (name.empty()) return "it is empty";
    if (name.size() > kMaxNameBytes) {
        return fmt::format("it is {} bytes long, more than {}", name.size(), kMaxNameBytes);
    }
    for (const char c : name) {
        if (!portable(c)) {
            return fmt::format("{} is not a letter, digit, '.', '_', '-' or '+'",
                               quote(std::string_view(&c, 1)));
        }
    }
    if (name.front() == '.' || name.front() == '-') {
        return fmt::format("it starts with '{}'", name.front());
    }
    return std::nullopt;
}

void check_name(std::string_view name, std::string_view what) {
    if (const auto why = name_problem(name)) {
        throw InputError(fmt::format("{} {} cannot name a file: {}", what, quote(name), *why));
    }
}

std::filesystem::path named_file(const std::filesystem::path& dir, std::string_view stem,
                                 std::string_view suffix) {
    const std::string name = std::string(stem) + std::string(suffix);
    const auto fail = [&](const std::string& why) {
        throw InputError((dir / name).string(), "cannot name a file: " + why);
    };
    if (name.empty() || name == "." || name == "..") fail("it names a folder");
    if (name.size() > kMaxFileNameBytes) {
        fail(fmt::format("it is {} bytes long, more than {}", name.size(), kMaxFileNameBytes));
    }
    for (const char c : name) {
        if (c == '/' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            fail(fmt::format("it holds {}", quote(std::string_view(&c, 1))));
        }
    }
    return dir / name;
}

}  // namespace hmcr
