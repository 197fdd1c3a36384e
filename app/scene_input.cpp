#include "app/scene_input.h"

#include <fmt/core.h>

namespace hmcr {

Scene load_scene_reporting(const std::string& name_or_path, bool quiet, SceneUse use) {
    const auto warn = [quiet](const std::string& w) {
        if (!quiet) fmt::print(stderr, "hmcr: warning: {}\n", w);
    };
    return load_scene(name_or_path, use, warn);
}

}  // namespace hmcr
