// Loading a scene on the command line: the loader's warnings go to stderr, one line each, and
// what it repaired in one summary line.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "meshes/scene.h"

namespace hmcr {

// The load options of every command that reads a scene.
struct SceneFlags {
    bool strict = false;   // refuse what the repairs would fix
    int mgf_segments = 0;  // 0: the scene file's, else kDefaultCurveSegments
};

void add_scene_flags(CLI::App& command, SceneFlags& flags);

// --view NAME, bound to `view`; an empty name is refused (without the flag, `view` stays empty:
// the scene's first view).
void add_view_flag(CLI::App& command, std::string& view);

Scene load_scene_reporting(const std::string& name_or_path, bool quiet,
                           SceneUse use = SceneUse::solve, const SceneFlags& flags = {});

}  // namespace hmcr
