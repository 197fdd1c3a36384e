// `make bench`: the shooting rate of hmcr against the Embree floor for the same work,
// measured in the same run on the same scene (issue 2's benchmark).
//
// For each scene and thread count: one full solve with the power oracle at 2,684,000 rays
// (rays/s = rays / shooting time, time per phase, leaves, memory), then the floor: the same
// number of incoherent first-hit rays (area-uniform origins, cosine directions), generated
// beforehand and traced through the EmbreeScene facade (one rtcIntersect1 each), median of 3.
#include <fmt/core.h>
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

void bench_scene(const std::string& name) {
    const Scene scene = load_scene(name);
    const PatchSet set = build_patch_set(scene.mesh);
    const EmbreeScene embree(set.patches);
    const std::vector<Ray> rays = incoherent_rays(set, kRays);
    fmt::print("\n{} ({} patches), power oracle, {} rays\n", name, set.patches.size(), kRays);
    fmt::print("{:>7} {:>8} {:>9} {:>8} {:>8} {:>8} {:>6} {:>10} {:>12} {:>7} {:>9}\n", "threads",
               "leaves", "iter", "setup s", "shoot s", "pushpull", "total", "rays/s",
               "embree rays/s", "ratio", "peak MiB");
    for (int threads : {1, 2}) {
        SolverOptions o;
        o.oracle = "power";
        o.rays = kRays;
        o.threads = threads;
        const Solution sol = solve(scene.mesh, o);
        const SolveStats& st = sol.stats;
        tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);
        const double floor = floor_seconds(embree, rays);
        const double rate = double(st.rays) / st.shooting_seconds;
        const double floor_rate = double(kRays) / floor;
        fmt::print("{:>7} {:>8} {:>9} {:>8.3f} {:>8.3f} {:>8.3f} {:>6.2f} {:>10.3g} {:>12.3g} {:>7.2f} {:>9.0f}\n",
                   threads, st.leaves, st.iterations.size(), st.setup_seconds, st.shooting_seconds,
                   st.push_pull_seconds, st.total_seconds, rate, floor_rate, floor_rate / rate,
                   double(peak_memory_bytes()) / (1 << 20));
    }
}

}  // namespace
}  // namespace hmcr

int main() {
    fmt::print("hmcr benchmark: shooting rate vs the Embree floor (ratio = floor rate / hmcr rate;\n"
               "1.0 would mean hmcr's shooting costs nothing beyond the first-hit queries).\n"
               "peak MiB is the process's peak resident memory so far.\n");
    for (const char* name : {"cornell", "cube-room"}) hmcr::bench_scene(name);
}
