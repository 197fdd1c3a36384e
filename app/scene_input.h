// Loading a scene on the command line: the loader's warnings go to stderr, one line each.
#pragma once

#include <string>

#include "meshes/scene.h"

namespace hmcr {

Scene load_scene_reporting(const std::string& name_or_path, bool quiet,
                           SceneUse use = SceneUse::solve);

}  // namespace hmcr
