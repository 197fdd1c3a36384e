// SPDX-License-Identifier: Apache-2.0
// Errors by audience (docs/usage.md#bad-input). An InputError is something the user can fix: a bad
// option, scene, file or folder; its what() is one line, "where: what" ("cornell.obj:12: ...").
// The command line answers it with exit code 2. Any other exception is a fault of hmcr (exit 1).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hmcr {

// `text` with its control characters written as escapes (\n, \x1b): a message stays one line
// whatever a file name, a JSON key or a token it quotes contains.
std::string one_line(std::string_view text);

// A place for a message: a path (or "path:line") of up to 300 characters whole, a longer one
// cut in the middle, keeping its start and its file name and line.
std::string shorten_place(std::string_view where);

class InputError : public std::runtime_error {
public:
    explicit InputError(std::string_view message) : std::runtime_error(one_line(message)) {}
    InputError(std::string_view where, std::string_view message)
        : std::runtime_error(one_line(shorten_place(where) + ": " + std::string(message))) {}
};

// "path:line", the place of a statement in a text file.
std::string at(const std::filesystem::path& path, int line);

// A token of user input for a message, in single quotes and cut short: a binary blob or a
// megabyte-long name must not flood the terminal.
std::string quote(std::string_view token);

// The plug-in of `registry` (common/registry.h) called name; throws InputError "unknown
// oracle 'x' (valid: power, ks, ...)" for a name it does not hold.
template <class Registry>
const auto& find_named(const Registry& registry, std::string_view name) {
    if (const auto* plugin = registry.find(name)) return *plugin;
    throw InputError("unknown " + registry.kind() + " " + quote(name) +
                     " (valid: " + registry.names() + ")");
}

}  // namespace hmcr
