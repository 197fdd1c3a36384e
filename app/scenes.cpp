// SPDX-License-Identifier: Apache-2.0
// `hmcr scenes`: the bundled scenes, by name.
#include <fmt/core.h>

#include <filesystem>

#include "app/command.h"
#include "common/data_directory.h"
#include "common/error.h"
#include "meshes/scene.h"

namespace hmcr {
namespace {

// The names, one a line, with control characters escaped (a folder's name is anyone's bytes);
// no scene folder, or none in it, is said, not listed as nothing.
int list_scenes() {
    const std::filesystem::path folder = scene_directory();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) {
        throw InputError(
            fmt::format("no bundled scenes: {} is not a folder (set {} to hmcr's data folder, the "
                        "one holding scenes/, or HMCR_SCENES to a scenes folder)",
                        folder.string(), kDataDirVariable));
    }
    const std::vector<std::string> names = bundled_scene_names();
    if (names.empty()) {
        throw InputError(folder.string(), "holds no bundled scene (a folder NAME with NAME.json)");
    }
    for (const std::string& name : names) fmt::print("{}\n", one_line(name));
    return 0;
}

}  // namespace

Command scenes_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("scenes", "list the bundled scenes");
    return {cmd, list_scenes};
}

}  // namespace hmcr
