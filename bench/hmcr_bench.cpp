// `make bench`: the shooting rate of hmcr against the Embree floor for the same work,
// measured in the same run on the same scene (issue 2's benchmark). floor/hmcr = how many
// times more rays per second Embree alone traces than a whole hmcr solve shoots; 1 would mean
// refinement and deposits cost nothing. peak_MiB is the process's peak so far.
//
// For each scene and thread count: one full solve with the power oracle at 2,684,000 rays
// (rays/s = rays / shooting time, time per phase, leaves, memory), then the floor: the same
// number of incoherent first-hit rays (area-uniform origins, cosine directions), generated
// beforehand and traced through the EmbreeScene facade (one rtcIntersect1 each), median of 3.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/embree_scene.h"
#include "radiosity/kernel.h"
#include "radiosity/rng.h"
#include "radiosity/run_summary.h"
#include "radiosity/sampling.h"
#include "radiosity/solver.h"

namespace hmcr {
namespace {

constexpr std::uint64_t kRays = 2'684'000;
using Clock = std::chrono::steady_clock;

struct Ray {
    Vec3 origin, direction;
};

std::vector<Ray> incoherent_rays(const PatchSet& set, std::uint64_t n) {
    std::vector<double> cumulative;
    double total = 0;
    for (const Patch& p : set.patches) cumulative.push_back(total += p.area);
    std::vector<Ray> rays(n);
    Rng rng(1234, 0);
    for (Ray& r : rays) {
        const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), rng.uniform() * total);
        const Patch& p = set.patches[std::min<std::size_t>(it - cumulative.begin(), set.patches.size() - 1)];
        r.origin = p.point(sample_element(p, Domain::root(), rng.uniform(), rng.uniform()));
        r.direction = sample_cosine_hemisphere(p.normal, rng.uniform(), rng.uniform());
    }
    return rays;
}

double floor_seconds(const EmbreeScene& scene, const std::vector<Ray>& rays) {
    std::vector<double> times;
    for (int rep = 0; rep < 3; ++rep) {
        const auto t0 = Clock::now();
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 4096), [&](const auto& r) {
            set_tracing_float_mode();
            for (std::size_t k = r.begin(); k < r.end(); ++k) {
                (void)scene.first_hit(rays[k].origin, rays[k].direction);
            }
        });
        times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    return times[1];
}

// One benchmark per scene and thread count; Google Benchmark prints the counters as a table.
void bench_solve(benchmark::State& state, const std::string& name) {
    const int threads = int(state.range(0));
    const Scene scene = load_scene(name);
    const PatchSet set = build_patch_set(scene.mesh);
    const EmbreeScene embree(set.patches);
    const std::vector<Ray> rays = incoherent_rays(set, kRays);
    for (auto _ : state) {
        SolverOptions o;
        o.oracle = "power";
        o.rays = kRays;
        o.threads = threads;
        const Solution sol = solve(scene.mesh, o);
        const SolveStats& st = sol.stats;
        state.SetIterationTime(st.total_seconds);
        tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);
        const double floor = floor_seconds(embree, rays);
        const double rate = double(st.rays) / st.shooting_seconds;
        state.counters["leaves"] = double(st.leaves);
        state.counters["setup_s"] = st.setup_seconds;
        state.counters["shoot_s"] = st.shooting_seconds;
        state.counters["pushpull_s"] = st.push_pull_seconds;
        state.counters["rays/s"] = rate;
        state.counters["embree_rays/s"] = double(kRays) / floor;
        state.counters["floor/hmcr"] = double(kRays) / floor / rate;
        state.counters["peak_MiB"] = double(peak_memory_bytes()) / (1 << 20);
    }
}

}  // namespace
}  // namespace hmcr

int main(int argc, char** argv) {
    for (const char* name : {"cornell", "cube-room"}) {
        benchmark::RegisterBenchmark((std::string("solve_power/") + name).c_str(), hmcr::bench_solve,
                                     std::string(name))
            ->Arg(1)
            ->Arg(2)
            ->ArgName("threads")
            ->Iterations(1)
            ->UseManualTime()
            ->Unit(benchmark::kSecond);
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
