// SPDX-License-Identifier: Apache-2.0
#include "app/scene_input.h"

#include <fmt/core.h>

#include "common/error.h"
#include "common/memory.h"
#include "common/text_file.h"

namespace hmcr {

void add_scene_flags(CLI::App& command, SceneFlags& flags) {
    command.add_flag("--strict", flags.strict,
                     "refuse polygons and materials that hmcr would otherwise repair "
                     "(docs/usage.md#repairs); a meshing study also refuses a cell finer than "
                     "its reference resolves");
    command
        .add_option("--mgf-segments", flags.mgf_segments,
                    fmt::format("segments per circle of MGF's curved surfaces (default: the scene "
                                "file's, else {})",
                                kDefaultCurveSegments))
        ->check(CLI::Range(kMinCurveSegments, kMaxCurveSegments));
    command
        .add_option("--sides", flags.sides,
                    fmt::format("sides of every material, 1 or 2 (default: the scene file's, else "
                                "MGF's sides statements, else {}; docs/usage.md#sides)",
                                kDefaultSides))
        ->check(CLI::Range(1, 2));
}

void add_view_flag(CLI::App& command, std::string& view) {
    command.add_option_function<std::string>(
        "--view",
        [&view](const std::string& name) {
            if (name.empty())
                throw InputError(
                    "view: the name is empty (without --view: the "
                    "scene's first view)");
            view = name;
        },
        "view name (default: the scene's first)");
}

namespace {

// Prints a load's warnings, up to kMaxWarningLines; finish() counts the others in one line.
class WarningPrinter {
public:
    explicit WarningPrinter(bool quiet) : m_quiet(quiet) {}

    void tell(const std::string& warning) {
        if (m_quiet || ++m_told > kMaxWarningLines) return;
        std::string line = one_line(warning);
        if (line.size() > kMaxWarningChars) {
            line = fmt::format("{} ... ({} characters)", line.substr(0, kMaxWarningChars),
                               line.size());
        }
        fmt::print(stderr, "hmcr: warning: {}\n", line);
    }

    void finish() const {
        if (m_told > kMaxWarningLines) {
            fmt::print(stderr, "hmcr: warning: {} more warnings not shown\n",
                       m_told - kMaxWarningLines);
        }
    }

private:
    bool m_quiet;
    std::size_t m_told = 0;
};

}  // namespace

Scene load_scene_reporting(const std::string& name_or_path, bool quiet, SceneUse use,
                           const SceneFlags& flags) {
    LoadOptions options;
    options.use = use;
    options.strict = flags.strict;
    if (flags.mgf_segments > 0) options.curve_segments = flags.mgf_segments;
    if (flags.sides > 0) options.sides = flags.sides;
    WarningPrinter printer(quiet);
    options.warn = [&printer](const std::string& w) { printer.tell(w); };
    Scene scene = [&] {  // returned in place: a patch mesh is not moved but copied
        try {
            return load_scene(name_or_path, options);
        } catch (...) {
            printer.finish();  // before the error's line, which stays the last
            throw;
        }
    }();
    printer.finish();
    return_freed_memory();
    if (!quiet && !scene.repairs.empty()) {
        // A strict load joins opposite faces too (docs/usage.md#repairs).
        const RepairReport& r = scene.repairs;
        const bool refusable = r.total() > r[RepairKind::sides_joined].count;
        fmt::print(stderr, "hmcr: repaired {}: {}{}\n", scene.mesh_path.string(), r.summary(),
                   refusable ? " (--strict refuses them)" : "");
    }
    return scene;
}

void warn_specular(const Scene& scene, bool quiet, SpecularUse use) {
    if (quiet) return;
    const FaceMaterials materials(scene.mesh);
    std::size_t specular = 0;
    for (auto f : scene.mesh.faces()) {
        const OpenMesh::Vec3d& ks = materials[f].specular;
        if (ks[0] > 0 || ks[1] > 0 || ks[2] > 0) ++specular;
    }
    if (specular == 0) return;
    fmt::print(stderr,
               "hmcr: warning: {} of {} patches of {} reflect specularly (Ks, rs): the radiosity "
               "engine absorbs that light (docs/design.md §1.2){}\n",
               specular, scene.mesh.n_faces(), scene.name,
               use == SpecularUse::render
                   ? ", so this image shows them with their diffuse radiosity alone, without "
                     "reflections; `hmcr trace` reflects them"
                   : "; `hmcr trace` reflects it");
}

void refuse_replacing_scene_files(const std::vector<std::filesystem::path>& outputs) {
    for (const std::filesystem::path& file : outputs) {
        std::error_code ec;
        if (file.extension() != ".json" || !std::filesystem::is_regular_file(file, ec)) continue;
        nlohmann::json j;
        try {
            j = read_json_file(file);
        } catch (const InputError&) {
            continue;  // no JSON: no scene file either
        }
        if (j.is_object() && j.contains("mesh")) {
            throw InputError(file.string(),
                             "is a scene file (it names a \"mesh\"), which this command's summary "
                             "would replace; give the output another name or folder");
        }
    }
}

}  // namespace hmcr
