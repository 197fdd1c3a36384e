// SPDX-License-Identifier: Apache-2.0
#include "studies/traced_reference.h"

#include <chrono>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_names.h"
#include "common/json_fields.h"
#include "common/stopwatch.h"
#include "common/text_file.h"
#include "rays/patch.h"
#include "studies/reference.h"
#include "viz/renderer.h"

namespace hmcr {

TracedReference compute_traced_reference(const Scene& scene, const std::vector<View>& views,
                                         TraceOptions options, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const PathTracer tracer(build_patch_set(scene.mesh), options.path);
    TracedReference ref;
    ref.views = trace_views(tracer, views, options, progress);
    ref.seconds = seconds_since(start);
    return ref;
}

std::map<std::string, TracedView> trace_views(const PathTracer& tracer,
                                              const std::vector<View>& views, TraceOptions options,
                                              Progress& progress) {
    options.sampler = &uniform_criterion();
    std::map<std::string, TracedView> out;
    for (const View& v : views) {
        PrefixedProgress view_progress(progress, "view " + v.name + ": ");
        TraceResult r = trace_image(tracer, v, options, view_progress);
        const double exposure = exposure_from(r.image);
        out[v.name] = {std::move(r.image), exposure, r.rays, r.seconds};
    }
    return out;
}

nlohmann::json write_view_images(OutputSet& out, const std::filesystem::path& dir,
                                 const std::map<std::string, TracedView>& views) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, v] : views) {
        write_pfm(out.temp(named_file(dir / "views", name, ".pfm")), v.image);
        write_png(out.temp(named_file(dir / "views", name, ".png")), v.image, v.exposure);
        j[name] = {{"exposure", v.exposure},
                   {"width", v.image.width},
                   {"height", v.image.height},
                   {"rays", v.rays},
                   {"seconds", v.seconds}};
    }
    return j;
}

std::vector<std::filesystem::path> traced_reference_files(const std::filesystem::path& dir,
                                                          const Scene& scene) {
    std::vector<std::filesystem::path> files{dir / "reference.json"};
    for (const View& v : scene.views) {
        files.push_back(named_file(dir / "views", v.name, ".pfm"));
        files.push_back(named_file(dir / "views", v.name, ".png"));
    }
    return files;
}

void write_traced_reference(OutputSet& out, const std::filesystem::path& dir, const Scene& scene,
                            const TracedReference& ref, const TraceOptions& o,
                            const std::string& command) {
    const nlohmann::json views = write_view_images(out, dir, ref.views);
    const nlohmann::json j = {{"command", command},
                              {"hmcr_version", HMCR_VERSION},
                              {"reference",
                               {{"kind", "traced"},
                                {"scene", scene.name},
                                {"sampler", "uniform"},
                                {"spp", o.spp},
                                {"seed", o.seed},
                                {"path",
                                 {{"estimator", estimator_name(o.path.estimator)},
                                  {"max_depth", o.path.max_depth},
                                  {"roulette_depth", o.path.roulette_depth}}},
                                {"seconds", ref.seconds},
                                {"views", views}}}};
    write_text_atomically(out.temp(dir / "reference.json"), j.dump(2) + "\n");
}

ReferenceKind reference_kind(const std::filesystem::path& dir) {
    return read_json_file(dir / "reference.json", [](const nlohmann::json& j) {
        const nlohmann::json& reference = json_member(j, {"reference"});
        const auto kind = json_object(reference, "reference").find("kind");
        if (kind == reference.end()) return ReferenceKind::mesh;
        const std::string name = json_string(*kind, "reference.kind");
        if (name == "traced") return ReferenceKind::traced;
        if (name == "points") return ReferenceKind::points;
        throw InputError("reference.kind " + quote(name) + " is not traced or points");
    });
}

std::map<std::string, TracedView> read_reference_views(const std::filesystem::path& dir,
                                                       const Scene& scene) {
    const std::map<std::string, double> exposure = read_reference_exposures(dir);
    std::map<std::string, TracedView> out;
    for (const View& v : scene.views) {
        if (!exposure.count(v.name)) {
            throw InputError((dir / "reference.json").string(),
                             "no view " + quote(v.name) + " of scene " + quote(scene.name));
        }
        const std::filesystem::path pfm = named_file(dir / "views", v.name, ".pfm");
        if (!std::filesystem::is_regular_file(pfm)) throw InputError(pfm.string(), "missing");
        try {
            out[v.name] = {read_pfm(pfm), exposure.at(v.name), 0, 0};
        } catch (const std::runtime_error& e) {
            throw InputError(e.what());
        }
    }
    return out;
}

}  // namespace hmcr
