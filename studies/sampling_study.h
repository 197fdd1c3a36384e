// SPDX-License-Identifier: Apache-2.0
// Sampling studies: every pixel sampling criterion at the same mean number of
// samples per pixel and seeds, measured against a reference (studies/traced_reference.h, or a
// radiosity reference's images), as Table 1 and Figures 4-6 of Rigau, Feixas, Sbert,
// "Refinement criteria based on f-divergences", EGSR 2003.
//
// A cell is one (spp, sampler, seed): every view of the scene traced at the reference image's
// size with that target spp (each adaptive sampler's threshold found by search, or its samples
// allocated from its map), quantised at the reference's exposure for the view and measured
// against the reference's image (studies/metrics.h).
//
// On disk (`hmcr study SCENE --reference REF --samplers LIST -o OUT`),
// CELL = SCENE-SAMPLER-sppN-sSEED:
//   OUT/cells/CELL.json            the cell's result, written atomically once the cell is done;
//                                  a rerun skips every cell whose file holds this cell made with
//                                  the same settings (resume); see studies/cell_files.h
//   OUT/images/CELL-VIEW.png       its image of each view (8-bit sRGB, the reference exposure)
//   OUT/density/CELL-VIEW.png      its sampling density map (image/density_map.h)
//   OUT/figures/VIEW-images.png    the reference, then every sampler's image of the first
//                                  seed, in the study's sampler order, 4 to a row, half size
//   OUT/figures/VIEW-density.png   every sampler's density map of the first seed, the same way
//                                  (with several spp values VIEW-sppN-images.png and
//                                  VIEW-sppN-density.png, one of each per spp)
//   OUT/table.json                 long form: options and every cell
//   OUT/table.csv                  one row per cell and view
//   OUT/table.md                   one row per sampler, mean +- standard error over seeds of
//                                  the errors averaged over the views; the RMSEp split into
//                                  bias and noise (from the seeds' images); one table per view;
//                                  all of it once per spp value
// A search that cannot reach the target (SppNotReached) is a result: the cell is written with
// status "failed" and its message, and the tables leave it out of the means.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/output_set.h"
#include "common/progress.h"
#include "meshes/scene.h"
#include "studies/metrics.h"
#include "studies/summary_table.h"
#include "trace/trace_image.h"

namespace hmcr {

struct SamplingStudyOptions {
    std::filesystem::path reference;  // a reference folder of either kind
    std::vector<const Criterion*> samplers = criterion_registry().all();
    int seeds = 3;                 // trace.seed .. trace.seed + seeds - 1
    std::vector<double> spps{60};  // target mean spp of the cells, in order
    TraceOptions trace;            // every cell's; sampler, spp, seed set per cell
    // Adaptive criteria judge display values (TraceOptions::criterion_exposure), at the
    // reference's exposure of each view
    bool display_criteria = false;
    std::filesystem::path output;  // the study folder
    // A folder's cells must all be made with the same settings (sampling_study_settings): a
    // rerun with other settings is refused, unless this is set, when such cells are redone.
    bool redo_other_settings = false;
    // The columns of table.md's and table.tex's tables per sampler, by
    // sampling_table_columns()'s names or "all"; empty: every one in table.md, its tex_default
    // in table.tex. Tables only: no cell setting.
    std::vector<std::string> columns;
};

struct SamplingView {
    ImageErrors errors;
    double spp = 0;  // achieved mean
    std::uint32_t min_spp = 0, max_spp = 0;
    double threshold = std::numeric_limits<double>::quiet_NaN();  // NaN for uniform
    std::uint64_t rays = 0;                                       // traced, the search's too
    double seconds = 0;
};

struct SamplingCell {
    std::string scene, sampler;
    double spp = 0;  // the target
    std::uint64_t seed = 0;
    nlohmann::json settings;    // sampling_study_settings() of the study that made it
    std::string status = "ok";  // "ok" or "failed"
    std::string message;        // why a search failed
    std::map<std::string, SamplingView> views;
    double seconds = 0;
    bool ok() const { return status == "ok"; }
};

// Throws InputError on options no sampling study can run with (an unknown or repeated sampler,
// no or a repeated spp value, seeds < 1, bad trace options): checked before anything is read
// or written.
void validate_sampling_study(const SamplingStudyOptions& options);

// What a cell's result depends on besides its sampler and seed: the scene's geometry, the
// reference (its path and the bytes of its reference.json), and the trace options but the
// thread count.
nlohmann::json sampling_study_settings(const Scene& scene, const SamplingStudyOptions& options);

// Runs (or resumes) the study; each cell is a note of `progress`. Throws InputError on bad
// options or an unusable reference, Interrupted (common/interrupt.h) between cells and between
// pixels after a SIGINT, SIGTERM or SIGHUP (finished cells stay).
void run_sampling_study(const Scene& scene, const SamplingStudyOptions& options,
                        Progress& progress = no_progress());

std::string sampling_cell_name(const std::string& scene, const std::string& sampler, double spp,
                               std::uint64_t seed);

// The cell files' JSON; non-finite numbers are stored as null.
nlohmann::json sampling_cell_to_json(const SamplingCell& cell);
SamplingCell sampling_cell_from_json(const nlohmann::json& j);

// The RMSEp split into bias and noise (studies/metrics.h) of every sampler with two or more
// successful seeds, by sampler and view: from the cells' images. SppErrorSplits: by spp.
using ErrorSplits = std::map<std::string, std::map<std::string, ErrorSplit>>;
using SppErrorSplits = std::map<double, ErrorSplits>;

// One sampler's split over all its views: the RMS of the views' biases and of their noises.
ErrorSplit rms_over_views(const std::map<std::string, ErrorSplit>& by_view);

// The files a sampling study writes at its end, once (its tables, figures and plot data):
// checked and locked before any cell, written as one set (common/output_set.h).
std::vector<std::filesystem::path> sampling_study_output_files(const Scene& scene,
                                                               const SamplingStudyOptions& options);

// The columns a sampling study's tables per sampler may hold (SamplingStudyOptions::columns),
// and those of table.tex by default: few enough to fit a 10 pt article's line unscaled.
TableColumns sampling_table_columns();

// table.json, table.csv, table.md, table.tex and plots/plot_data.json, from every cell of the
// study in order, into `out`, the set of sampling_study_output_files().
void write_sampling_tables(OutputSet& out, const std::string& scene,
                           const SamplingStudyOptions& options,
                           const std::vector<std::string>& views,
                           const std::vector<SamplingCell>& cells,
                           const SppErrorSplits& splits = {});

}  // namespace hmcr
