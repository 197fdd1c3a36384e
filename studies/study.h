// Meshing studies (SPEC section 6): every oracle at one or more element budgets and seeds,
// measured against a converged reference (studies/reference.h) in image and object space.
//
// A "cell" is one (budget, oracle, seed): a budget search for epsilon, the shaded mesh of the
// accepted solve, renders of every view of the scene with the reference's fixed exposure, the
// image metrics of each view and the object-space error relative to the reflected radiosity.
//
// On disk (`hmcr study SCENE --reference REF -o OUT`), CELL = SCENE-ORACLE-B{budget}-s{seed}:
//   OUT/meshes/CELL.vtp            the cell's solution
//   OUT/images/CELL-VIEW.png       its image of every view (8-bit sRGB, the reference exposure)
//   OUT/cells/CELL.json            the cell's result, written atomically once the cell is done;
//                                  a rerun skips every cell whose file exists (resume)
//   OUT/table.json                 long form: options and every cell (cell_to_json)
//   OUT/table.csv                  one row per cell and view
//   OUT/table.md                   per budget, one row per oracle: mean +- standard error over
//                                  seeds, best error of each column in bold
//   OUT/plots/error_vs_elements.png  object-space error against leaves, log-log, per oracle
//
// A failed budget search (std::invalid_argument) is a result, not an error: the cell is written
// with status "failed" and its message, and the tables leave it out of the means.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "radiosity/budget_search.h"
#include "studies/metrics.h"
#include "studies/object_space_error.h"

namespace hmcr {

struct StudyOptions {
    std::string scene;                 // bundled name or scene file
    std::filesystem::path reference;   // folder written by write_reference
    std::vector<std::size_t> budgets;  // target leaf counts
    std::vector<std::string> oracles;  // names; "all" expands to every registered oracle
    int seeds = 3;                     // seeds first_seed .. first_seed + seeds - 1
    std::uint64_t first_seed = 1;
    std::uint64_t rays = 2'684'000;  // shooting rays of every solve
    int lines = 10;                  // N_s
    double budget_tolerance = 0.01;  // relative distance to the budget accepted
    int samples_per_axis = 2;        // supersampling of the images
    std::filesystem::path output;    // the study folder
    int threads = 0;                 // 0: all cores
    double crease_degrees = 30;      // Gouraud blending limit of the shaded meshes
};

struct CellResult {
    std::string scene, oracle;
    std::size_t budget = 0;
    std::uint64_t seed = 0;
    std::string status = "ok";  // "ok" or "failed"
    std::string message;        // why a search failed
    double epsilon = 0;         // of the accepted probe
    std::size_t leaves = 0;     // reached
    std::vector<BudgetProbe> probes;
    double seconds = 0;  // wall time of the budget search (every probe)
    std::map<std::string, ImageErrors> views;
    ObjectError object_error;
    bool ok() const { return status == "ok"; }
};

struct StudyProgress {
    enum class Stage { kSkipped, kProbe, kMeasuring, kDone, kFailed };
    Stage stage = Stage::kProbe;
    std::size_t cell_index = 0;  // 0-based, in the order budget x oracle x seed
    std::size_t cell_count = 0;
    std::string cell;               // its name, CELL above
    int probe = 0;                  // kProbe: 1-based index of the probe just finished
    BudgetProbe last_probe;         // kProbe: its epsilon, leaves and time
    double elapsed_seconds = 0;     // since run_study started
    double remaining_seconds = -1;  // estimate from the cells computed so far; < 0: unknown
};

using StudyProgressFn = std::function<void(const StudyProgress&)>;

// Runs (or resumes) the study. Throws std::invalid_argument on bad options (unknown oracle,
// no budget, seeds < 1) and std::runtime_error naming the file when the reference is unusable.
void run_study(const StudyOptions& options, const StudyProgressFn& progress = {});

std::string cell_name(const std::string& scene, const std::string& oracle, std::size_t budget,
                      std::uint64_t seed);

// The cell files' JSON; non-finite numbers are stored as null (PSNR of identical images).
nlohmann::json cell_to_json(const CellResult& cell);
CellResult cell_from_json(const nlohmann::json& j);

// table.json, table.csv, table.md and the plot, from every cell of the study in order.
void write_study_tables(const StudyOptions& options, const std::vector<std::string>& views,
                        const std::vector<CellResult>& cells);

}  // namespace hmcr
