// `make bench`: every oracle on `cornell` and `cube-room` at 2,684,000 rays and N_s = 10, at an
// epsilon giving about 19,000 leaves, on 1 and 2 threads, against the Embree floor of the same
// work measured in the same run: the same number of incoherent first-hit rays plus, for the
// line-based oracles, the same number of occlusion lines, cast N_s at a time between random
// leaf pairs of the solution (bench/embree_floor.h). floor_x = hmcr shooting time / floor time;
// 1 would mean refinement, sampling and deposits cost nothing (issue 3's target for kl: 2).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <map>
#include <string>
#include <utility>

#include "bench/embree_floor.h"
#include "meshes/scene.h"
#include "oracles/registry.h"
#include "radiosity/solver.h"

namespace hmcr::bench {
namespace {

constexpr std::uint64_t kRays = 2'684'000;
constexpr int kLines = 10;

// Epsilon for about 19,000 leaves at kRays, N_s = 10, seed 1 (found by bisection on log eps).
const std::map<std::pair<std::string, std::string>, double> kEpsilon = {
    {{"cornell", "power"}, 1.18e-06},   {{"cornell", "ks"}, 5.9e-03},
    {{"cornell", "mi"}, 3.57e-08},      {{"cornell", "kl"}, 6.6e-07},
    {{"cornell", "cs"}, 1.4e-06},       {{"cornell", "hl"}, 2.23e-07},
    {{"cornell", "vt"}, 8.2e-05},       {{"cube-room", "power"}, 4.92e-05},
    {{"cube-room", "ks"}, 5.38e-03},    {{"cube-room", "mi"}, 3.25e-08},
    {{"cube-room", "kl"}, 4.08e-05},    {{"cube-room", "cs"}, 8.64e-05},
    {{"cube-room", "hl"}, 1.14e-05},    {{"cube-room", "vt"}, 1.19e-04},
};

void bench_solve(benchmark::State& state, const std::string& scene_name, const std::string& oracle) {
    const int threads = int(state.range(0));
    const Scene scene = load_scene(scene_name);
    const PatchSet set = build_patch_set(scene.mesh);
    const EmbreeScene embree(set.patches);
    const std::vector<Ray> rays = incoherent_rays(set, kRays);
    for (auto _ : state) {
        SolverOptions o;
        o.oracle = oracle;
        o.epsilon = kEpsilon.at({scene_name, oracle});
        o.rays = kRays;
        o.lines = kLines;
        o.threads = threads;
        const Solution sol = solve(scene.mesh, o);
        const SolveStats& st = sol.stats;
        state.SetIterationTime(st.shooting_seconds);
        tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);
        double floor = first_hit_seconds(embree, rays);
        if (st.lines_cast > 0) {
            const auto segments = pair_segments(*sol.hierarchy, st.lines_cast / kLines, kLines);
            floor += occlusion_seconds(embree, segments, kLines);
        }
        const double lookups = double(st.cache_hits + st.oracle_evaluations);
        state.counters["leaves"] = double(st.leaves);
        state.counters["rays/s"] = double(st.rays) / st.shooting_seconds;
        state.counters["evals"] = double(st.oracle_evaluations);
        state.counters["lines"] = double(st.lines_cast);
        state.counters["hit_rate"] = lookups > 0 && st.cache_capacity ? st.cache_hits / lookups : 0;
        state.counters["oracle_cpu_s"] = st.oracle_seconds;
        state.counters["pushpull_s"] = st.push_pull_seconds;
        state.counters["floor_s"] = floor;
        state.counters["floor_x"] = st.shooting_seconds / floor;
        state.counters["tree+cache_MiB"] = double(st.hierarchy_bytes + st.cache_bytes) / (1 << 20);
    }
}

}  // namespace
}  // namespace hmcr::bench

int main(int argc, char** argv) {
    for (const char* scene : {"cornell", "cube-room"}) {
        for (const hmcr::Oracle* o : hmcr::all_oracles()) {
            const std::string oracle(o->name());
            if (!hmcr::bench::kEpsilon.count({scene, oracle})) continue;
            benchmark::RegisterBenchmark((std::string(scene) + "/" + oracle).c_str(),
                                         hmcr::bench::bench_solve, std::string(scene), oracle)
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
}
