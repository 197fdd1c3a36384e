// SPDX-License-Identifier: Apache-2.0
#include "studies/sampling_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <set>

#include "common/error.h"
#include "common/file_names.h"
#include "common/hash.h"
#include "common/output_set.h"
#include "common/stopwatch.h"
#include "common/text_file.h"
#include "image/density_map.h"
#include "rays/patch.h"
#include "studies/cell_handout.h"
#include "studies/montage.h"
#include "studies/plot_data.h"
#include "studies/traced_reference.h"
#include "trace/criteria/registry.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

void validate(const SamplingStudyOptions& o) {
    if (o.samplers.empty()) throw InputError("study: no sampler given");
    std::set<const Criterion*> samplers;
    for (const Criterion* c : o.samplers) {
        if (!samplers.insert(c).second) {
            throw InputError(fmt::format("study: sampler {} is given twice", c->name()));
        }
    }
    if (o.seeds < 1) throw InputError("study: seeds must be at least 1");
    if (o.spps.empty()) throw InputError("study: no spp given");
    std::set<double> spps;  // n log n: a study may list a thousand
    for (double spp : o.spps) {
        if (!spps.insert(spp).second) {
            throw InputError(fmt::format("study: spp {} is given twice", spp));
        }
    }
    check_study_size(std::uint64_t(o.samplers.size()) * o.spps.size(), o.seeds, o.trace.seed);
    if (o.spps.size() > kMaxPlotPoints) {
        throw InputError(fmt::format("study: {} spp values; at most {}, the points a plot shows",
                                     o.spps.size(), kMaxPlotPoints));
    }
    if (o.output.empty()) throw InputError("study: no output folder given");
    chosen_columns(o.columns, sampling_table_columns(), "sampling");
    for (double spp : o.spps)
        for (const Criterion* s : o.samplers) {
            TraceOptions t = o.trace;
            t.sampler = s;
            t.spp = spp;
            validate_trace_options(t);  // the spp target each sampler can reach
        }
}

// OUT/figures/VIEW-KIND.png, or VIEW-sppN-KIND.png in a study of several spp values.
fs::path figure_file(const SamplingStudyOptions& o, const View& view, double spp,
                     const char* kind) {
    const std::string stem =
        o.spps.size() == 1 ? view.name : fmt::format("{}-spp{:g}", view.name, spp);
    return named_file(o.output / "figures", stem + "-" + kind, ".png");
}

struct CellTask {
    const Criterion* sampler = nullptr;
    double spp = 0;
    std::uint64_t seed = 0;
    std::string name;
};

class SamplingStudy {
public:
    SamplingStudy(const Scene& scene, const SamplingStudyOptions& o, Progress& progress);
    void run();

private:
    // OUT/FOLDER/STEM.EXTENSION, the stem a cell's name, CELL-VIEW or a view's.
    fs::path file(const char* folder, const std::string& stem, const char* extension) const {
        return named_file(m_options.output / folder, stem, extension);
    }
    std::vector<fs::path> outputs(std::size_t index) const;
    std::optional<SamplingCell> previous_cell(std::size_t index);
    SamplingCell compute(std::size_t index, FileBatch& files);
    SamplingView trace_view(const CellTask& t, const View& view, Progress& notes, FileBatch& files);
    void write_figures(OutputSet& out, const View& view, double spp) const;
    SppErrorSplits error_splits(const std::vector<SamplingCell>& cells) const;
    std::string where(std::size_t i) const {
        return fmt::format("[{}/{}] {}", i + 1, m_tasks.size(), m_tasks[i].name);
    }

    const Scene& m_scene;
    const SamplingStudyOptions& m_options;
    Progress& m_progress;
    std::vector<CellTask> m_tasks;
    nlohmann::json m_settings;
    std::map<std::string, TracedView> m_reference;
    std::map<std::string, Image8> m_reference8;  // quantised at the view's exposure
    std::unique_ptr<PathTracer> m_tracer;
    std::optional<OutputSet> m_tables;  // rank 0's
};

SamplingStudy::SamplingStudy(const Scene& scene, const SamplingStudyOptions& o, Progress& progress)
    : m_scene(scene), m_options(o), m_progress(progress) {
    validate(o);
    for (double spp : o.spps)
        for (const Criterion* s : o.samplers)
            for (int k = 0; k < o.seeds; ++k) {
                const std::uint64_t seed = o.trace.seed + std::uint64_t(k);
                m_tasks.push_back(
                    {s, spp, seed,
                     sampling_cell_name(scene.name, std::string(s->name()), spp, seed)});
            }
    // Rank 0 writes the tables and figures: it alone checks, locks and holds them, before any
    // work; every rank learns of a refusal.
    together(Ranks::world(), [&] {
        if (Ranks::world().root()) {
            m_tables.emplace(sampling_study_output_files(scene, o), o.output);
        }
    });
    m_settings = sampling_study_settings(scene, o);
}

std::optional<SamplingCell> SamplingStudy::previous_cell(std::size_t index) {
    const CellTask& t = m_tasks[index];
    CellFileRule<SamplingCell> rule;
    rule.parse = sampling_cell_from_json;
    rule.is_this_cell = [&](const SamplingCell& c) {
        return c.scene == m_scene.name && c.sampler == t.sampler->name() && c.spp == t.spp &&
               c.seed == t.seed;
    };
    rule.settings = m_settings;
    rule.redo_other_settings = m_options.redo_other_settings;
    rule.lacks = [this](const SamplingCell& c) {
        std::vector<std::string> views;
        for (const View& v : m_scene.views) views.push_back(v.name);
        return c.ok() ? missing_view(c.views, views) : std::string();
    };
    CellNotes notes(m_progress, where(index) + ": ");
    return read_previous_cell(file("cells", t.name, ".json"), rule, notes);
}

// Every file a cell writes, for the checks before any cell is computed.
std::vector<fs::path> SamplingStudy::outputs(std::size_t index) const {
    const CellTask& t = m_tasks[index];
    std::vector<fs::path> files{file("cells", t.name, ".json")};
    for (const View& v : m_scene.views) {
        files.push_back(file("images", t.name + "-" + v.name, ".png"));
        files.push_back(file("density", t.name + "-" + v.name, ".png"));
    }
    return files;
}

void SamplingStudy::run() {
    m_reference = read_reference_views(m_options.reference, m_scene);
    for (const auto& [name, v] : m_reference) m_reference8[name] = quantise(v.image, v.exposure);
    for (const CellTask& t : m_tasks) {  // every cell's memory, before the first
        TraceOptions o = m_options.trace;
        o.sampler = t.sampler;
        o.spp = t.spp;
        for (const auto& [name, v] : m_reference) {
            View sized;
            sized.width = v.image.width;
            sized.height = v.image.height;
            check_trace_memory(o, sized);
        }
    }
    m_tracer = std::make_unique<PathTracer>(build_patch_set(m_scene.mesh), m_options.trace.path);
    CellLoop<SamplingCell> loop;
    loop.count = m_tasks.size();
    loop.previous = [this](std::size_t i) { return previous_cell(i); };
    loop.compute = [this](std::size_t i, FileBatch& files) { return compute(i, files); };
    loop.to_json = sampling_cell_to_json;
    loop.from_json = sampling_cell_from_json;
    loop.file = [this](std::size_t i) { return file("cells", m_tasks[i].name, ".json"); };
    loop.outputs = [this](std::size_t i) { return outputs(i); };
    loop.where = [this](std::size_t i) { return where(i); };
    loop.outcome = [](const SamplingCell& c) { return c.status; };
    const std::vector<SamplingCell> cells = run_cells_on(Ranks::world(), loop, m_progress);
    if (!Ranks::world().root()) return;  // rank 0 writes the tables
    std::vector<std::string> views;
    for (const View& v : m_scene.views) {
        views.push_back(v.name);
        for (double spp : m_options.spps) write_figures(*m_tables, v, spp);
    }
    write_sampling_tables(*m_tables, m_scene.name, m_options, views, cells, error_splits(cells));
    m_tables->commit();
}

SppErrorSplits SamplingStudy::error_splits(const std::vector<SamplingCell>& cells) const {
    // The finished cells by sampler and spp, found in one pass (a study may have thousands).
    std::map<std::pair<std::string, double>, std::vector<const SamplingCell*>> seeds;
    for (const SamplingCell& c : cells) {
        if (c.ok()) seeds[{c.sampler, c.spp}].push_back(&c);
    }
    SppErrorSplits splits;
    for (const auto& [key, of_seeds] : seeds) {
        const auto& [sampler, spp] = key;
        for (const View& v : m_scene.views) {
            std::vector<Image8> images;
            for (const SamplingCell* c : of_seeds) {
                const fs::path png =
                    file("images",
                         sampling_cell_name(c->scene, c->sampler, c->spp, c->seed) + "-" + v.name,
                         ".png");
                if (fs::exists(png)) images.push_back(read_png(png));
            }
            if (images.size() >= 2)
                splits[spp][sampler][v.name] = split_error(images, m_reference8.at(v.name));
        }
    }
    return splits;
}

SamplingCell SamplingStudy::compute(std::size_t index, FileBatch& files) {
    const CellTask& t = m_tasks[index];
    SamplingCell cell{
        m_scene.name, std::string(t.sampler->name()), t.spp, t.seed, m_settings, "ok", "", {}, 0};
    const auto start = Clock::now();
    for (const View& v : m_scene.views) {
        CellNotes notes(m_progress, where(index) + ": view " + v.name + ": ");
        try {
            cell.views[v.name] = trace_view(t, v, notes, files);
        } catch (const SppNotReached& e) {
            cell.status = "failed";
            cell.message = "view " + v.name + ": " + e.what();
            cell.views.clear();
            break;
        }
    }
    cell.seconds = seconds_since(start);
    return cell;
}

// The view at the reference image's size, traced, written (into the cell's batch) and measured.
SamplingView SamplingStudy::trace_view(const CellTask& t, const View& view, Progress& notes,
                                       FileBatch& files) {
    const TracedView& ref = m_reference.at(view.name);
    View v = view;
    v.width = ref.image.width;
    v.height = ref.image.height;
    TraceOptions o = m_options.trace;
    o.sampler = t.sampler;
    o.spp = t.spp;
    o.seed = t.seed;
    if (m_options.display_criteria) o.criterion_exposure = ref.exposure;
    const TraceResult r = trace_image(*m_tracer, v, o, notes);
    const Image8 image = quantise(r.image, ref.exposure);
    const std::string name = t.name + "-" + v.name;
    write_png(files.temp(file("images", name, ".png")), image);
    write_png(files.temp(file("density", name, ".png")), density_map(r.samples, v.width, v.height));
    const SampleCounts c = r.counts();
    return {image_errors(image, m_reference8.at(v.name)),
            c.mean,
            c.min,
            c.max,
            r.threshold,
            r.rays_traced,
            r.seconds};
}

// The first seed's images and density maps of every sampler at one spp (a white tile where a
// cell failed), each tile labelled with its sampler (and "failed" under a white tile).
void SamplingStudy::write_figures(OutputSet& out, const View& view, double spp) const {
    const Image8& ref = m_reference8.at(view.name);
    std::vector<Image8> images{ref}, maps;
    std::vector<std::string> image_labels{"reference"}, map_labels;
    for (const Criterion* sampler : m_options.samplers) {
        const std::string name = sampling_cell_name(m_scene.name, std::string(sampler->name()), spp,
                                                    m_options.trace.seed) +
                                 "-" + view.name;
        const fs::path image = file("images", name, ".png"), map = file("density", name, ".png");
        const bool ok = fs::exists(image) && fs::exists(map);
        Image8 blank(ref.width, ref.height);
        for (Srgb8& p : blank.pixels) p = {255, 255, 255};
        images.push_back(ok ? read_png(image) : blank);
        maps.push_back(ok ? read_png(map) : blank);
        const std::string label = std::string(sampler->name()) + (ok ? "" : " failed");
        image_labels.push_back(label);
        map_labels.push_back(label);
    }
    const int shrink = ref.width >= 128 ? 2 : 1;
    write_png(out.temp(figure_file(m_options, view, spp, "images")),
              montage(images, 4, shrink, image_labels));
    write_png(out.temp(figure_file(m_options, view, spp, "density")),
              montage(maps, 4, shrink, map_labels));
}

}  // namespace

std::vector<fs::path> sampling_study_output_files(const Scene& scene,
                                                  const SamplingStudyOptions& o) {
    std::vector<fs::path> files{o.output / "table.json", o.output / "table.csv",
                                o.output / "table.md", o.output / "table.tex",
                                plot_data_file(o.output)};
    for (const View& v : scene.views) {
        for (double spp : o.spps) {
            files.push_back(figure_file(o, v, spp, "images"));
            files.push_back(figure_file(o, v, spp, "density"));
        }
    }
    return files;
}

std::string sampling_cell_name(const std::string& scene, const std::string& sampler, double spp,
                               std::uint64_t seed) {
    return fmt::format("{}-{}-spp{:g}-s{}", scene, sampler, spp, seed);
}

void validate_sampling_study(const SamplingStudyOptions& options) { validate(options); }

nlohmann::json sampling_study_settings(const Scene& scene, const SamplingStudyOptions& o) {
    const TraceOptions& t = o.trace;
    const std::string reference_json = read_text_file(o.reference / "reference.json");
    return {{"scene", scene.name},
            {"geometry", geometry_hash(scene.mesh)},
            {"reference_json_hash", text_hash(reference_json)},
            {"spp_tolerance", t.spp_tolerance},
            {"max_spp", t.max_spp.value_or(0)},  // 0: the default
            {"tree_depth", t.tree_depth},
            {"display_criteria", o.display_criteria},
            {"fresh", t.fresh},
            {"allocation", allocation_name(t.allocation)},
            {"path",
             {{"estimator", estimator_name(t.path.estimator)},
              {"max_depth", t.path.max_depth},
              {"roulette_depth", t.path.roulette_depth}}}};
}

void run_sampling_study(const Scene& scene, const SamplingStudyOptions& options,
                        Progress& progress) {
    SamplingStudy(scene, options, progress).run();
}

}  // namespace hmcr
