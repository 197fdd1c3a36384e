// `hmcr scenes`: the bundled scenes, by name.
#include <fmt/core.h>

#include "app/command.h"
#include "meshes/scene.h"

namespace hmcr {

Command scenes_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("scenes", "list the bundled scenes");
    return {cmd, [] {
                for (const auto& name : bundled_scene_names()) fmt::print("{}\n", name);
                return 0;
            }};
}

}  // namespace hmcr
