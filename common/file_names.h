// Names that become parts of file names (docs/design.md §5.7): a view's name (views/VIEW.pfm,
// CELL-VIEW.png) and the scene, oracle and sampler names in a study's cell names. Such a name
// holds only the POSIX portable file name characters and '+' (A-Z a-z 0-9 . _ - +), does not
// start with '.' or '-', and is short: it can name no folder but its own ("..", "/"), no hidden
// file, no option, and no line break in a message. Every file name hmcr makes from a name goes
// through named_file(), which checks the result again: a name that slipped past its reader
// still cannot lead a write out of its folder.
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

// Why `name` cannot be part of a file name ("it is empty", "'/' is not a letter, digit, '.',
// '_', '-' or '+'", ...), or nothing when it can. max_bytes: its longest allowed length.
std::optional<std::string> name_problem(std::string_view name,
                                        std::size_t max_bytes = kMaxNameBytes);

// Throws InputError "WHAT 'NAME' cannot name a file: why" unless name_problem() has nothing.
void check_name(std::string_view name, std::string_view what);

// dir / (stem + suffix), the one way hmcr turns a name into a file name: throws InputError
// naming the file unless stem + suffix passes name_problem() with kMaxFileNameBytes, so the
// result is always a file directly inside `dir`.
std::filesystem::path named_file(const std::filesystem::path& dir, std::string_view stem,
                                 std::string_view suffix);

}  // namespace hmcr
