// `make bench`: every oracle on `cornell` and `cube-room` at 2,684,000 rays and N_s = 10, at an
// epsilon giving about 19,000 leaves, on 1 and 2 threads, against the Embree floor of the same
// work measured in the same run: the same number of incoherent first-hit rays plus, for the
// line-based oracles, the same number of occlusion lines, cast N_s at a time between random
// leaf pairs of the solution (bench/embree_floor.h). floor_x = hmcr shooting time / floor time;
// 1 would mean refinement, sampling and deposits cost nothing.
//
// Then the scaling study (bench/scaling.h), each point in a process of its own so that its peak
// memory is its own. Every row, both kinds, goes to --results (bench/results.json).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_row.h"
#include "bench/scaling.h"
#include "common/atomic_file.h"
#include "oracles/registry.h"

namespace hmcr::bench {
namespace {

// Epsilon for about 19,000 leaves at kBenchRays, N_s = 10, seed 1 (bisection on log eps).
const std::map<std::pair<std::string, std::string>, double> kEpsilon = {
    {{"cornell", "power"}, 1.18e-06},   {{"cornell", "ks"}, 5.9e-03},
    {{"cornell", "mi"}, 3.57e-08},      {{"cornell", "kl"}, 6.6e-07},
    {{"cornell", "cs"}, 1.4e-06},       {{"cornell", "hl"}, 2.23e-07},
    {{"cornell", "vt"}, 8.2e-05},       {{"cube-room", "power"}, 4.92e-05},
    {{"cube-room", "ks"}, 5.38e-03},    {{"cube-room", "mi"}, 3.25e-08},
    {{"cube-room", "kl"}, 4.08e-05},    {{"cube-room", "cs"}, 8.64e-05},
    {{"cube-room", "hl"}, 1.14e-05},    {{"cube-room", "vt"}, 1.19e-04},
};

std::vector<nlohmann::json> g_rows;

void bench_solve(benchmark::State& state, const std::string& scene, const std::string& oracle) {
    RowSpec spec{scene, oracle, kEpsilon.at({scene, oracle}), kBenchRays, int(state.range(0))};
    for (auto _ : state) {
        const RowResult r = run_row(spec);
        state.SetIterationTime(r.shooting_seconds);
        state.counters["leaves"] = double(r.leaves);
        state.counters["rays/s"] = double(r.rays) / r.shooting_seconds;
        state.counters["evals"] = double(r.oracle_evaluations);
        state.counters["lines"] = double(r.lines_cast);
        state.counters["hit_rate"] = r.cache_hit_rate;
        state.counters["oracle_cpu_s"] = r.oracle_seconds;
        state.counters["floor_s"] = r.floor_seconds;
        state.counters["floor_x"] = r.floor_x();
        state.counters["tree+cache_MiB"] = double(r.solver_bytes) / (1 << 20);
        nlohmann::json row = to_json(r);
        row["study"] = "oracles";
        g_rows.push_back(row);
    }
}

// Removes "--NAME VALUE" from argv (before Google Benchmark sees it); "" when absent.
std::string take_flag(int& argc, char** argv, const char* name) {
    for (int k = 1; k + 1 < argc; ++k) {
        if (std::strcmp(argv[k], name) != 0) continue;
        std::string value = argv[k + 1];
        for (int j = k; j + 2 < argc + 1; ++j) argv[j] = argv[j + 2];
        argc -= 2;
        return value;
    }
    return "";
}

}  // namespace
}  // namespace hmcr::bench

int main(int argc, char** argv) {
    using namespace hmcr::bench;
    // A scaling point, run by the scaling study in a process of its own.
    if (argc == 7 && std::strcmp(argv[1], "--row") == 0) return run_row_process(argv + 2);
    const std::string results = take_flag(argc, argv, "--results");
    const std::string scaling = take_flag(argc, argv, "--scaling");
    for (const char* scene : {"cornell", "cube-room"}) {
        for (const hmcr::Oracle* o : hmcr::oracle_registry().all()) {
            const std::string oracle(o->name());
            if (!kEpsilon.count({scene, oracle})) continue;
            benchmark::RegisterBenchmark((std::string(scene) + "/" + oracle).c_str(), bench_solve,
                                         std::string(scene), oracle)
                ->Arg(1)
                ->Arg(2)
                ->ArgName("threads")
                ->Iterations(1)
                ->UseManualTime()
                ->Unit(benchmark::kSecond);
        }
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (!scaling.empty()) {
        const std::filesystem::path plot =
            std::filesystem::path(results.empty() ? "." : results).parent_path() / "scaling.png";
        for (nlohmann::json& row : run_scaling_study(argv[0], scaling, plot)) g_rows.push_back(row);
    }
    if (!results.empty()) {
        hmcr::write_text_atomically(results, nlohmann::json{{"rows", g_rows}}.dump(2) + "\n");
        fmt::print("bench: {} rows in {}\n", g_rows.size(), results);
    }
}
