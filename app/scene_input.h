// SPDX-License-Identifier: Apache-2.0
// Loading a scene on the command line: the loader's warnings go to stderr, one line each and
// at most kMaxWarningLines of them, and what it repaired in one summary line.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "meshes/scene.h"

namespace hmcr {

// The load options of every command that reads a scene.
struct SceneFlags {
    bool strict = false;   // refuse what the repairs would fix
    int mgf_segments = 0;  // 0: the scene file's, else kDefaultCurveSegments
    int sides = 0;         // 0: the scene file's, else each material's (docs/usage.md#sides)
};

// Warnings printed by one load at most (docs/usage.md#bad-input); the rest are counted in one
// more line. Each is cut to kMaxWarningChars characters.
inline constexpr std::size_t kMaxWarningLines = 20;
inline constexpr std::size_t kMaxWarningChars = 1000;

void add_scene_flags(CLI::App& command, SceneFlags& flags);

// --view NAME, bound to `view`; an empty name is refused (without the flag, `view` stays empty:
// the scene's first view).
void add_view_flag(CLI::App& command, std::string& view);

Scene load_scene_reporting(const std::string& name_or_path, bool quiet,
                           SceneUse use = SceneUse::solve, const SceneFlags& flags = {});

// What a radiosity command does with specular surfaces, which the engine absorbs
// (docs/design.md §1.2): `solve` (a solve, a reference, a meshing study) or `render` (an image of
// a radiosity solution).
enum class SpecularUse { solve, render };

// One warning line when some of the scene's patches reflect specularly (Ks, rs), saying how
// many and what the command makes of them; nothing otherwise or when quiet.
void warn_specular(const Scene& scene, bool quiet, SpecularUse use);

// Throws InputError when one of `outputs` is an existing scene file (a JSON object naming a
// "mesh"): a summary named after the output (`solve dir/X.obj -o dir/X.vtp` writes dir/X.json)
// would replace the scene file beside its mesh. Another file there, or one that is no JSON, is
// an earlier summary's place and is replaced as before.
void refuse_replacing_scene_files(const std::vector<std::filesystem::path>& outputs);

}  // namespace hmcr
