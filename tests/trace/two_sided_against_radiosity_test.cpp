// SPDX-License-Identifier: Apache-2.0
// The path tracer against the radiosity solve on a scene with a two-sided partition lit from
// both sides (docs/design.md §1.3, §10.1): both solve the same light transport, so each side's
// mean radiance agrees within their noise and the solve's mesh error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "radiosity/solver.h"
#include "tests/support/plugins.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"
#include "trace/path_tracer.h"
#include "trace/trace_image.h"

namespace hmcr::test::two_sided_against_radiosity {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kPartition = 6;  // the face after the box's six
// The solve's error from its elements being constant, relative to the side's mean: 0.2-0.5% on
// this scene at 2e7 rays (docs/testing.md), bounded here by 1%. The solve runs to a stop of
// 1e-4, so that the light left unshot (1% of the emitted power at the default stop) is not
// part of the difference.
constexpr double kMeshError = 0.01;
constexpr double kStop = 1e-4;

// A grey room [0, 2] x [0, 1] x [0, 1.5] (rho 0.5) cut in two by a unit square partition at
// x = 1 (z up to 1, light passes above it), two-sided: its front faces the left half (rho 0.6),
// its back the right (rho 0.3). A small emitter under the ceiling of each half, E = 10 on the
// left, 4 on the right: each side of the partition is lit from its half and, over the top and
// off the walls, from the other.
std::vector<TestPolygon> partitioned_room() {
    std::vector<TestPolygon> scene =
        inward_box({0, 0, 0}, {2, 1, 1.5}, 1, Rgb::Constant(0.5), Rgb::Zero());
    TestPolygon partition = axis_rectangle(0, 1, {0, 0}, {1, 1}, false);
    partition.reflectance = Rgb::Constant(0.6);
    partition.two_sided = true;
    partition.back_reflectance = Rgb::Constant(0.3);
    scene.push_back(partition);
    for (const auto& [x, e] : {std::pair{0.3, 10.0}, std::pair{1.3, 4.0}}) {
        TestPolygon light = axis_rectangle(2, 1.49, {x, 0.3}, {x + 0.4, 0.7}, false);
        light.emission = Rgb::Constant(e);
        scene.push_back(light);
    }
    return scene;
}

// The side's mean radiosity over its leaves, by area.
double side_mean(const Hierarchy& h, std::uint8_t side) {
    double power = 0, area = 0;
    h.for_each_leaf_of(side, [&](const Element& e) {
        if (e.id.patch != kPartition) return;
        power += e.area * e.radiosity[1];
        area += e.area;
    });
    return power / area;
}

struct SideMeans {
    std::vector<double> front, back;  // one per seed
};

// The side means of independent solves (seeds 1, 2, ...), 200,000 rays each, the power oracle.
SideMeans solve_seeds(const PatchMesh& mesh, int seeds) {
    SideMeans m;
    for (int s = 1; s <= seeds; ++s) {
        SolverOptions o;
        o.oracle = test::oracle("power");
        o.rays = 200'000;
        o.seed = std::uint64_t(s);
        o.stop = kStop;
        const Solution sol = solve(mesh, o);
        m.front.push_back(side_mean(*sol.hierarchy, kFront));
        m.back.push_back(side_mean(*sol.hierarchy, kBack));
    }
    return m;
}

// A view half-way between the partition and the wall behind it, 90 degrees wide, its image
// plane parallel to the partition: it sees exactly the unit square, and the mean of its pixels
// (each a jittered sample of its own part) is the side's mean radiance. The pixels' spread is
// mostly the radiance's variation over the side, not noise: the standard error comes from two
// independent images instead, the mean of (a - b) / 2 having the noise of the mean of (a + b) / 2.
Estimate traced_side(const PathTracer& tracer, double x) {
    std::vector<Image> images;
    for (const std::uint64_t seed : {7, 8}) {
        TraceOptions o;
        o.spp = 16;
        o.seed = seed;
        images.push_back(
            trace_image(tracer, test_view({x, 0.5, 0.5}, {1, 0.5, 0.5}, 90, 32), o).image);
    }
    std::vector<double> sum, half_difference;
    for (std::size_t i = 0; i < images[0].pixels.size(); ++i) {
        const double a = images[0].pixels[i][1], b = images[1].pixels[i][1];
        sum.push_back((a + b) / 2);
        half_difference.push_back((a - b) / 2);
    }
    return {estimate_mean(sum).mean, estimate_mean(half_difference).standard_error, sum.size()};
}

TEST(TwoSidedAgainstRadiosity, EachSideOfAPartitionHasTheSolvesMeanRadiance) {
    const PatchMesh mesh = make_patch_mesh(partitioned_room());
    const SideMeans solved = solve_seeds(mesh, 8);
    const PathTracer tracer(build_patch_set(mesh), PathOptions{});
    struct Side {
        const char* name;
        const std::vector<double>& radiosity;
        double camera_x;
    };
    for (const Side& s : {Side{"front", solved.front, 0.5}, Side{"back", solved.back, 1.5}}) {
        const Estimate b = estimate_mean(s.radiosity), l = traced_side(tracer, s.camera_x);
        // Two independent estimates: their difference's standard error from both variances.
        const double se = std::hypot(l.standard_error, b.standard_error / kPi);
        EXPECT_TRUE(within_standard_errors(std::string(s.name) + " side, traced - solved",
                                           l.mean - b.mean / kPi, 0, se,
                                           kMeshError * b.mean / kPi));
    }
}

}  // namespace
}  // namespace hmcr::test::two_sided_against_radiosity
