// SPDX-License-Identifier: Apache-2.0
// Names that become parts of file names (docs/design.md §5.7). A name a user's file gives (a
// view's, which names views/VIEW.pfm and a study's CELL-VIEW.png) holds only the POSIX portable
// file name characters and '+' (A-Z a-z 0-9 . _ - +), does not start with '.' or '-', and is
// short: it can name no folder but its own ("..", "/"), no hidden file, no option, and no line
// break in a message. Every file name hmcr makes from a name (a view's, a cell's, a scene's)
// goes through named_file(), which makes sure the result is a file directly inside its folder:
// a name that slipped past its reader still cannot lead a write out of it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace hmcr {

// The longest name a scene file may give a view, and a study's scene name.
inline constexpr std::size_t kMaxNameBytes = 64;
// The longest file name (one path component) hmcr makes: Linux's NAME_MAX.
inline constexpr std::size_t kMaxFileNameBytes = 255;

// Why `name` cannot be a name that becomes part of file names ("it is empty", "'/' is not a
// letter, digit, '.', '_', '-' or '+'", ...), or nothing when it can.
std::optional<std::string> name_problem(std::string_view name);

// Throws InputError "WHAT 'NAME' cannot name a file: why" unless name_problem() has nothing.
void check_name(std::string_view name, std::string_view what);

// dir / (stem + suffix), the one way hmcr turns a name into a file name. Throws InputError
// naming the file unless stem + suffix is one path component, of 1 to kMaxFileNameBytes bytes,
// neither "." nor "..", without '/', NUL or another control character: the result is always a
// file directly inside `dir`.
std::filesystem::path named_file(const std::filesystem::path& dir, std::string_view stem,
                                 std::string_view suffix);

}  // namespace hmcr
