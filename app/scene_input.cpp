#include "app/scene_input.h"

#include <fmt/core.h>

namespace hmcr {

Scene load_scene_reporting(const std::string& name_or_path, bool quiet, SceneUse use) {
    Scene scene = load_scene(name_or_path, use);
    if (!quiet) {
        for (const std::string& w : scene.warnings) fmt::print(stderr, "hmcr: warning: {}\n", w);
    }
    return scene;
}

}  // namespace hmcr
