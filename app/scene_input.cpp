#include "app/scene_input.h"

#include <fmt/core.h>

#include "common/error.h"
#include "common/memory.h"

namespace hmcr {

void add_scene_flags(CLI::App& command, SceneFlags& flags) {
    command.add_flag("--strict", flags.strict,
                     "refuse polygons and materials that hmcr would otherwise repair "
                     "(docs/usage.md#repairs)");
    command
        .add_option("--mgf-segments", flags.mgf_segments,
                    fmt::format("segments per circle of MGF's curved surfaces (default: the scene "
                                "file's, else {})",
                                kDefaultCurveSegments))
        ->check(CLI::Range(kMinCurveSegments, kMaxCurveSegments));
}

void add_view_flag(CLI::App& command, std::string& view) {
    command.add_option_function<std::string>(
        "--view",
        [&view](const std::string& name) {
            if (name.empty()) throw InputError("view: the name is empty (without --view: the "
                                               "scene's first view)");
            view = name;
        },
        "view name (default: the scene's first)");
}

Scene load_scene_reporting(const std::string& name_or_path, bool quiet, SceneUse use,
                           const SceneFlags& flags) {
    LoadOptions options;
    options.use = use;
    options.strict = flags.strict;
    if (flags.mgf_segments > 0) options.curve_segments = flags.mgf_segments;
    options.warn = [quiet](const std::string& w) {
        if (!quiet) fmt::print(stderr, "hmcr: warning: {}\n", w);
    };
    Scene scene = load_scene(name_or_path, options);
    return_freed_memory();
    if (!quiet && !scene.repairs.empty()) {
        fmt::print(stderr, "hmcr: repaired {}: {} (--strict refuses them)\n",
                   scene.mesh_path.string(), scene.repairs.summary());
    }
    return scene;
}

}  // namespace hmcr
