// SPDX-License-Identifier: Apache-2.0
#include "bench/control_variate.h"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/solver.h"

namespace hmcr::bench {
namespace {

constexpr double kElements = 4000;          // the uniform mesh's size, about
constexpr std::uint64_t kRays = 1'000'000;  // per solve

struct Spread {
    double variance = 0;  // mean over leaves and channels, (W/m^2)^2
    double mean_b = 0;    // mean over leaves and channels of the mean B
    double seconds = 0;   // per solve
    std::size_t leaves = 0;
    std::size_t negative = 0;  // leaves with B < 0 in some channel, over all seeds
};

Spread spread(const Scene& scene, ControlVariate cv, int seeds) {
    std::vector<Rgb> sum, sum2;
    Spread s;
    const double total_area = build_patch_set(scene.mesh).total_area;
    for (int seed = 1; seed <= seeds; ++seed) {
        SolverOptions o;
        o.rays = kRays;
        o.seed = std::uint64_t(seed);
        o.uniform_max_area = total_area / kElements;
        o.min_area = 0;  // as a reference's uniform mesh (studies/reference.cpp)
        o.max_depth = 24;
        o.control_variate = cv;
        const Solution sol = solve(scene.mesh, o);
        s.seconds += sol.stats.total_seconds / seeds;
        std::size_t k = 0;
        sol.hierarchy->for_each_leaf_of(kFront, [&](const Element& e) {
            if (sum.size() <= k) sum.emplace_back(Rgb::Zero()), sum2.emplace_back(Rgb::Zero());
            sum[k] += e.radiosity;
            sum2[k] += e.radiosity * e.radiosity;
            s.negative += (e.radiosity < 0).any();
            ++k;
        });
        s.leaves = k;
    }
    const double n = seeds;
    for (std::size_t k = 0; k < sum.size(); ++k) {
        const Rgb mean = sum[k] / n;
        s.variance += ((sum2[k] - n * mean * mean) / (n - 1)).mean() / double(sum.size());
        s.mean_b += mean.mean() / double(sum.size());
    }
    return s;
}

}  // namespace

int run_control_variate_study(int seeds) {
    fmt::print(
        "| scene | leaves | mean B | var B, none | var B, constant | gain | s/solve, none | "
        "s/solve, constant | negative leaves |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const char* name : {"cornell", "cube-room", "furnace", "plates", "shadow", "mgf-room"}) {
        const Scene scene = load_scene(name);
        const Spread none = spread(scene, ControlVariate::none, seeds);
        const Spread cv = spread(scene, ControlVariate::constant, seeds);
        const std::string gain =
            cv.variance > 0 ? fmt::format("{:.3g}", none.variance / cv.variance) : "exact";
        fmt::print("| {} | {} | {:.4g} | {:.4g} | {:.4g} | {} | {:.2f} | {:.2f} | {} |\n", name,
                   none.leaves, none.mean_b, none.variance, cv.variance, gain, none.seconds,
                   cv.seconds, cv.negative);
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace hmcr::bench
