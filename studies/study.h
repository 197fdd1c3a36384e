// SPDX-License-Identifier: Apache-2.0
// Meshing studies (docs/design.md §6): every oracle at one or more element budgets and seeds,
// measured against a converged reference (studies/reference.h) in image and object space.
//
// A "cell" is one (budget, oracle, seed): a budget search for epsilon, the shaded mesh of the
// accepted solve, renders of every view of the scene with the reference's fixed exposure, the
// image metrics of each view and the object-space error relative to the reflected radiosity.
//
// On disk (`hmcr study SCENE --reference REF -o OUT`), CELL = SCENE-ORACLE-B{budget}-s{seed}:
//   OUT/meshes/CELL.vtp            the cell's solution
//   OUT/images/CELL-VIEW.png       its image of every view (8-bit sRGB, the reference exposure)
//   OUT/meshes/CELL-mesh.vtp, OUT/images/CELL-mesh-VIEW.png: the same of the frozen re-solve
//   OUT/cells/CELL.json            the cell's result, written atomically once the cell is done;
//                                  a rerun skips every cell whose file exists (resume)
//   OUT/table.json                 long form: options and every cell (cell_to_json)
//   OUT/table.csv                  one row per cell and view
//   OUT/table.md, OUT/table.tex    per budget, one row per oracle: mean +- standard error over
//                                  seeds, the bold of studies/summary_table.h
//   OUT/plots/error_vs_elements.png  object-space error against leaves, log-log, per oracle
//   OUT/figures/VIEW-B{budget}-images.png, -meshes.png: every oracle's image and mesh side by side
//   OUT/meshes.pvsm, OUT/meshes.pvd: every cell's mesh in ParaView (studies/study_figures.h)
//
// The mesh error: each cell's final mesh is solved again frozen (the same leaves, no oracle)
// with many more rays and measured the same way. The cell's own error is what a user of its
// rays gets; the frozen one is, up to the little noise left, the error of the mesh the oracle
// chose.
//
// A failed budget search (BudgetNotReached) is a result, not an error: the cell is written
// with status "failed" and its message, and the tables leave it out of the means.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/output_set.h"
#include "common/progress.h"
#include "meshes/scene.h"
#include "radiosity/budget_search.h"
#include "studies/metrics.h"
#include "studies/object_space_error.h"
#include "studies/summary_table.h"

namespace hmcr {

// The frozen re-solve's default rays per ray of the cell: its noise is then a seventh of the
// cell's (1/sqrt(50)), small beside every mesh error measured.
inline constexpr std::uint64_t kMeshRaysPerCellRay = 50;

struct StudyOptions {
    std::filesystem::path reference;   // folder written by write_reference
    std::vector<std::size_t> budgets;  // target leaf counts
    std::vector<const Oracle*> oracles = oracle_registry().all();  // each budget's cells
    int seeds = 3;         // seeds solver.seed .. solver.seed + seeds - 1
    SolverOptions solver;  // every cell's solve; oracle, epsilon, seed set per cell
    // > 0: each budget's cells shoot rays_per_leaf x budget rays instead of solver.rays.
    std::uint64_t rays_per_leaf = 0;
    // Rays of the frozen re-solve (mesh error): 0 for none; by default kMeshRaysPerCellRay x
    // the cell's rays.
    std::optional<std::uint64_t> mesh_rays;
    double budget_tolerance = 0.01;          // relative distance to the budget accepted
    int samples_per_axis = 2;                // supersampling of the images
    std::filesystem::path output;            // the study folder
    double crease_degrees = kCreaseDegrees;  // Gouraud blending limit of the shaded meshes
    // A folder's cells must all be made with the same settings (study_settings): a rerun with
    // other settings is refused, unless this is set, when such cells are computed again.
    bool redo_other_settings = false;
    // Refuse a cell whose leaves are finer than the reference resolves (kFinerShareLimit of
    // studies/reference_resolution.h) instead of warning.
    bool strict = false;
    // The columns of table.md and table.tex, by study_table_columns()'s names or "all"; empty:
    // every one in table.md, its tex_default in table.tex. Tables only: no cell setting.
    std::vector<std::string> columns;
};

struct CellResult {
    std::string scene, oracle;
    std::size_t budget = 0;
    std::uint64_t seed = 0;
    nlohmann::json settings;    // study_settings() of the study that made it
    std::string status = "ok";  // "ok" or "failed"
    std::string message;        // why a search failed
    double epsilon = 0;         // of the accepted probe
    std::size_t leaves = 0;     // reached
    std::vector<BudgetProbe> probes;
    double seconds = 0;  // wall time of the budget search (every probe)
    std::map<std::string, ImageErrors> views;
    ObjectError object_error;
    // The share of the solution's area in leaves finer than the reference resolves there
    // (studies/reference_resolution.h); NaN where the reference has no resolution (traced).
    double finer_share = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t rays = 0;       // of the cell's solves
    std::uint64_t mesh_rays = 0;  // of the frozen re-solve; 0: no mesh error measured
    std::map<std::string, ImageErrors> mesh_views;
    ObjectError mesh_object_error;
    bool ok() const { return status == "ok"; }
};

// Throws InputError on options no study can run with (no budget, an unknown or repeated oracle or
// budget, seeds < 1, a bad solver setting): checked before anything is read or written.
void validate_study(const StudyOptions& options);

// Runs (or resumes) the study; each cell is a note of `progress` (skipped, its probes, done or
// failed, the time left). Throws InputError on bad options (unknown oracle, no budget, seeds < 1)
// or an unusable reference.
void run_study(const Scene& scene, const StudyOptions& options, Progress& progress = no_progress());

// The rays of a cell at `budget`, and of its frozen re-solve.
std::uint64_t cell_rays(const StudyOptions& options, std::size_t budget);
std::uint64_t cell_mesh_rays(const StudyOptions& options, std::size_t budget);
// options.mesh_rays as the tables and cell settings record it: a count, or "50x" by default.
nlohmann::json mesh_rays_json(const StudyOptions& options);

std::string cell_name(const std::string& scene, const std::string& oracle, std::size_t budget,
                      std::uint64_t seed);

// What a cell's result depends on besides its oracle, budget and seed: the scene's geometry,
// the reference (its path and the bytes of its reference.json), and every setting of the solve
// and of the measurement, except those that change no result (threads, cache size).
nlohmann::json study_settings(const Scene& scene, const StudyOptions& options);

// The cell files' JSON; non-finite numbers are stored as null (PSNR of identical images).
nlohmann::json cell_to_json(const CellResult& cell);
CellResult cell_from_json(const nlohmann::json& j);

// The files a study writes at its end, once (its tables and plot data, and the figures and
// ParaView files of studies/study_figures.h): checked and locked before any cell, written as one
// set (common/output_set.h). The plots drawn from the plot data come after the set
// (docs/studies.md, "Plots"). study_table_files: the tables and plot data alone.
std::vector<std::filesystem::path> study_output_files(const Scene& scene,
                                                      const StudyOptions& options);
std::vector<std::filesystem::path> study_table_files(const StudyOptions& options);

// The one-line warning of table.md and of the study's end, naming the cells at `budget` whose
// finer share is above kFinerShareLimit (studies/reference_resolution.h); empty where none is.
std::string finer_warning(const std::vector<CellResult>& cells, std::size_t budget);

// The columns a meshing study's table.md and table.tex may hold (StudyOptions::columns), and
// those of table.tex by default: few enough to fit a 10 pt article's line unscaled.
TableColumns study_table_columns();

// table.json, table.csv, table.md, table.tex and the plot data, from every cell of the study in
// order, into `out`, a set holding study_table_files().
void write_study_tables(OutputSet& out, const std::string& scene, const StudyOptions& options,
                        const std::vector<std::string>& views,
                        const std::vector<CellResult>& cells);

}  // namespace hmcr
