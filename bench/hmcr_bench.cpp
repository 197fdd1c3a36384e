// SPDX-License-Identifier: Apache-2.0
// `make bench`: every oracle on `cornell` and `cube-room` at 2,684,000 rays and N_s = 10, at an
// epsilon giving about 19,000 leaves, on 1 and 2 threads, against the Embree floor of the same
// work measured in the same run: the same number of first-hit rays, traced as the solve traces
// its rays, plus, for the line-based oracles, the same number of occlusion lines, cast N_s at a
// time between random leaf pairs of the solution (bench/embree_floor.h). floor_x = hmcr
// shooting time / floor time; 1 would mean refinement, sampling and deposits cost nothing.
// Every ray of those rows refines; then `power` and `kl` on both scenes at the default refine
// share, the solve users run (a refining pass, then the frozen pass), against the floor of all
// its rays (--default-share runs those rows alone).
//
// Then the scaling study (bench/scaling.h), each point in a process of its own so that its peak
// memory is its own. Every row, both kinds, goes to --results (bench/results.json), and the
// scaling study's curves to scaling_plot_data.json beside it, which scripts/plot_study.py draws.
// A plain program: each row is a whole solve of seconds, timed by the row itself (bench_row.h);
// a microbenchmark library's repetitions and statistics have nothing to add (docs/decisions.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_row.h"
#include "bench/control_variate.h"
#include "bench/scaling.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "radiosity/oracle_registry.h"
#include "radiosity/solver_options.h"
#include "radiosity/solver_settings.h"

namespace hmcr::bench {
namespace {

// Epsilon for about 19,000 leaves at kBenchRays, N_s = 10, seed 1 (bisection on log eps).
const std::map<std::pair<std::string, std::string>, double> kEpsilon = {
    {{"cornell", "power"}, 1.18e-06}, {{"cornell", "ks"}, 5.9e-03},
    {{"cornell", "mi"}, 3.57e-08},    {{"cornell", "kl"}, 6.6e-07},
    {{"cornell", "cs"}, 1.4e-06},     {{"cornell", "hl"}, 2.23e-07},
    {{"cornell", "vt"}, 8.2e-05},     {{"cube-room", "power"}, 4.92e-05},
    {{"cube-room", "ks"}, 5.38e-03},  {{"cube-room", "mi"}, 3.25e-08},
    {{"cube-room", "kl"}, 4.08e-05},  {{"cube-room", "cs"}, 8.64e-05},
    {{"cube-room", "hl"}, 1.14e-05},  {{"cube-room", "vt"}, 1.19e-04},
};

void print_header() {
    fmt::print("{:>9} {:>6} {:>7} {:>7} {:>9} {:>9} {:>9} {:>7} {:>10} {:>9} {:>9} {:>8}\n",
               "scene", "oracle", "threads", "leaves", "shoot s", "rays/s", "floor s", "x floor",
               "evals", "lines", "hit rate", "MiB");
}

// Runs a row, prints its line of the table and returns its JSON row, labelled `study`.
nlohmann::json run_and_print(const RowSpec& spec, const char* study) {
    const RowResult r = run_row(spec);
    fmt::print(
        "{:>9} {:>6} {:>7} {:>7} {:>9.2f} {:>9.3g} {:>9.3f} {:>7.2f} {:>10} "
        "{:>9} {:>9.3f} {:>8.0f}\n",
        spec.scene, spec.oracle, spec.threads, r.leaves, r.shooting_seconds,
        double(r.rays) / r.shooting_seconds, r.floor_seconds, r.floor_x(), r.oracle_evaluations,
        r.lines_cast, r.cache_hit_rate, double(r.solver_bytes) / (1 << 20));
    nlohmann::json row = to_json(r);
    row["study"] = study;
    return row;
}

// Every oracle on both scenes, 1 and 2 threads, every ray refining: a line of the table each,
// and its JSON row.
std::vector<nlohmann::json> run_oracle_rows(RaySequence sequence) {
    fmt::print("sequence {}\n", name(sequence));
    print_header();
    std::vector<nlohmann::json> rows;
    for (const char* scene : {"cornell", "cube-room"}) {
        for (const Oracle* o : oracle_registry().all()) {
            const std::string oracle(o->name());
            if (!kEpsilon.count({scene, oracle})) continue;
            for (int threads : {1, 2}) {
                rows.push_back(run_and_print(
                    {scene, oracle, kEpsilon.at({scene, oracle}), kBenchRays, threads, 1, sequence},
                    "oracles"));
            }
        }
    }
    return rows;
}

// The solve users run, at the default refine share: `power` and `kl` on both scenes at the
// same epsilon, a tenth of the rays refining and the rest frozen, against the floor of all its
// rays (and the refining pass's lines).
std::vector<nlohmann::json> run_default_share_rows(RaySequence sequence) {
    fmt::print("default refine share {}, sequence {}\n", SolverOptions{}.refine_share,
               name(sequence));
    print_header();
    std::vector<nlohmann::json> rows;
    for (const char* scene : {"cornell", "cube-room"}) {
        for (const char* oracle : {"power", "kl"}) {
            for (int threads : {1, 2}) {
                rows.push_back(
                    run_and_print({scene, oracle, kEpsilon.at({scene, oracle}), kBenchRays, threads,
                                   SolverOptions{}.refine_share, sequence},
                                  "default-share"));
            }
        }
    }
    return rows;
}

}  // namespace
}  // namespace hmcr::bench

int main(int argc, char** argv) {
    using namespace hmcr::bench;
    // A scaling point, run by the scaling study in a process of its own.
    if (argc == 7 && std::strcmp(argv[1], "--row") == 0) return run_row_process(argv + 2);
    CLI::App app{
        "hmcr_bench: every oracle against the Embree floor, then the scaling study "
        "(docs/performance.md)"};
    std::string results, scaling;
    int cv_seeds = 0;
    bool default_share_only = false;
    hmcr::RaySequence sequence = hmcr::SolverOptions{}.sequence;
    app.add_option("--results", results, "write every row here (JSON)");
    app.add_option("--scaling", scaling,
                   "run the scaling study on the generated office scenes in this folder");
    app.add_option("--control-variate", cv_seeds,
                   "run only the control variate's study over this many seeds")
        ->check(CLI::PositiveNumber);
    app.add_flag("--default-share", default_share_only,
                 "run only the rows of the default refine share (refine, then freeze)");
    app.add_option_function<std::string>(
        "--sequence",
        [&sequence](const std::string& v) {
            hmcr::SolverOptions chosen;  // the solver's own reading, and its message
            try {
                hmcr::apply_settings({{"sequence", v}}, chosen);
            } catch (const hmcr::InputError& e) {
                throw CLI::ValidationError(e.what());
            }
            sequence = chosen.sequence;
        },
        "the table's ray sequence, random or sobol (default: the solver's)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        fmt::print(stderr, "hmcr_bench: error: {} (see hmcr_bench --help)\n", e.what());
        return 2;
    }
    if (cv_seeds > 0) return run_control_variate_study(cv_seeds);
    std::vector<nlohmann::json> rows;
    if (!default_share_only) rows = run_oracle_rows(sequence);
    for (nlohmann::json& row : run_default_share_rows(sequence)) rows.push_back(row);
    if (!scaling.empty() && !default_share_only) {
        const std::filesystem::path plot_data =
            std::filesystem::path(results.empty() ? "." : results).parent_path() /
            "scaling_plot_data.json";
        for (nlohmann::json& row : run_scaling_study(argv[0], scaling, plot_data))
            rows.push_back(row);
    }
    if (!results.empty()) {
        hmcr::write_text_atomically(results, nlohmann::json{{"rows", rows}}.dump(2) + "\n");
        fmt::print("bench: {} rows in {}\n", rows.size(), results);
    }
}
