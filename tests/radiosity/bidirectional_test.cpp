// SPDX-License-Identifier: Apache-2.0
// Lines used both ways (docs/design.md §3.13): exact where the one-way estimator is exact, the
// same expectation where it is a mean, the one-way bits where the far end has nothing to shoot,
// the power balance ray by ray, and the same bits for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/solver.h"
#include "tests/support/analytic.h"
#include "tests/support/energy_balance.h"
#include "tests/support/furnace.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

SolverOptions both_ways(std::uint64_t rays, std::uint64_t seed, double max_area) {
    SolverOptions o;
    o.rays = rays;
    o.seed = seed;
    o.uniform_max_area = max_area;
    o.bidirectional = Bidirectional::yes;
    return o;
}

constexpr RaySequence kSequences[] = {RaySequence::random, RaySequence::sobol};

// The furnace: both ends of every line shoot the same Delta B, so each carries half of Phi each
// way, and every leaf keeps the K-bounce value in expectation (t test per patch over 16 seeds);
// also on a refined-then-frozen solve, whose frozen pass uses its lines both ways.
TEST(BothWays, FurnaceOnAUniformAndAFrozenMesh) {
    const double rho = 0.5, e = 1;
    for (const RaySequence sequence : kSequences) {
        for (const double max_area : {1.0 / 64, 0.0}) {
            SCOPED_TRACE(testing::Message() << name(sequence) << ", max area " << max_area);
            const auto mesh = make_patch_mesh(
                inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(rho), Rgb::Constant(e)));
            expect_furnace_per_patch(mesh, rho, e, 16, [&](std::uint64_t seed) {
                SolverOptions o = both_ways(30'000, seed, max_area);
                o.sequence = sequence;
                o.epsilon = 1e-4;
                o.lines = 4;
                return o;
            });
        }
    }
}

// Two unit squares d = 0.1 m apart, fronts facing, one leaf each, E = 1 below and 2 above, rho =
// 0.5: each sees the other with F, so Jacobi's iterations swap and scale the unshot radiosity,
// Delta B^(k+1) = rho F (Delta B_2^k, Delta B_1^k), and after K iterations each holds
// sum_(k<=K) Delta B^k. Both ends shoot, with different strengths (1 : 2 at first): a t test per
// plate over 12 seeds against that sum. The stop rule (1%) falls between two iterations' unshot
// power with a wide margin, so K is the same for every seed.
TEST(BothWays, TwoFacingEmittersHoldTheJacobiSums) {
    const double rho = 0.5, d = 0.1, f = parallel_rectangles(1, 1, d);
    auto plate = [&](double z, bool up, double e) {
        TestPolygon p = axis_rectangle(2, z, {0, 0}, {1, 1}, up);
        p.reflectance = Rgb::Constant(rho);
        p.emission = Rgb::Constant(e);
        return p;
    };
    const auto mesh = make_patch_mesh({plate(0, true, 1), plate(d, false, 2)});
    for (const RaySequence sequence : kSequences) {
        SCOPED_TRACE(name(sequence));
        std::vector<double> low, high;
        std::size_t iterations = 0;
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            SolverOptions o = both_ways(100'000, seed, 1.0);
            o.sequence = sequence;
            const Solution sol = solve(mesh, o);
            ASSERT_EQ(sol.stats.leaves, 2u);
            if (seed == 1) iterations = sol.stats.iterations.size();
            ASSERT_EQ(sol.stats.iterations.size(), iterations);
            double b[2] = {1, 2}, unshot[2] = {1, 2};
            for (std::size_t k = 0; k < iterations; ++k) {
                const double next[2] = {rho * f * unshot[1], rho * f * unshot[0]};
                for (int p = 0; p < 2; ++p) b[p] += unshot[p] = next[p];
            }
            low.push_back(sol.hierarchy->root(0).radiosity[1] - b[0]);
            high.push_back(sol.hierarchy->root(1).radiosity[1] - b[1]);
        }
        EXPECT_TRUE(t_test("lower plate's B minus the Jacobi sum", low, 0, 0, 2));
        EXPECT_TRUE(t_test("upper plate's B minus the Jacobi sum", high, 0, 0, 2));
    }
}

// A closed box whose faces emit 1 or 2, on a fixed mesh of 8 x 8 leaves a face: one way and
// both ways have the same expectation (paired t test of one patch's B over seeds, the same K).
TEST(BothWays, SameExpectationAsOneWayInAClosedBox) {
    std::vector<TestPolygon> box =
        inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(0.5), Rgb::Constant(1));
    for (std::size_t p = 0; p < box.size() / 2; ++p) box[p].emission = Rgb::Constant(2);
    const auto mesh = make_patch_mesh(box);
    for (const RaySequence sequence : kSequences) {
        SCOPED_TRACE(name(sequence));
        std::vector<double> difference;
        for (std::uint64_t seed = 1; seed <= 16; ++seed) {
            SolverOptions o = both_ways(20'000, seed, 1.0 / 64);
            o.sequence = sequence;
            const Solution both = solve(mesh, o);
            o.bidirectional = Bidirectional::no;
            const Solution one = solve(mesh, o);
            ASSERT_EQ(both.stats.iterations.size(), one.stats.iterations.size());
            const std::size_t patch = box.size() - 1;  // an emitter of 1
            difference.push_back(both.hierarchy->root(patch).radiosity[0] -
                                 one.hierarchy->root(patch).radiosity[0]);
        }
        EXPECT_TRUE(t_test("B both ways minus B one way", difference, 0));
    }
}

// The plates of solver_test: the emitter (rho = 0) has nothing to shoot once it has shot, the
// receiver nothing before it is lit, so no line has two ends with unshot power and the solve is
// the one-way one, bit for bit.
TEST(BothWays, PlatesKeepTheOneWayBits) {
    SolverOptions o = both_ways(50'000, 4, 1.0 / 16);
    const Solution both = solve(unit_plates(0.5), o);
    o.bidirectional = Bidirectional::no;
    expect_same_leaves(*both.hierarchy, *solve(unit_plates(0.5), o).hierarchy);
}

// docs/design.md §8.4 ray by ray: per channel, what the lines carried (both ways) is what the
// leaves absorbed and reflected, what escaped and what the back faces took, to rounding (the
// Cornell box on a fixed mesh).
TEST(BothWays, ShotPowerIsAbsorbedReflectedEscapedOrLost) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = both_ways(300'000, 5, 0);
    o.uniform_max_area = build_patch_set(scene.mesh).total_area / 2000;
    expect_energy_balance(solve(scene.mesh, o), false);
}

// Every back deposit in ray order: the same leaves and values with 1 and 2 threads, for both
// sequences, with the control variate's zero surfaces (one way) beside the leaves' lines.
TEST(BothWays, SameBitsForOneAndTwoThreads) {
    const Scene scene = load_scene("cornell");
    for (const RaySequence sequence : kSequences) {
        for (const ControlVariate cv : {ControlVariate::none, ControlVariate::constant}) {
            SolverOptions o = both_ways(60'000, 3, 0);
            o.uniform_max_area = build_patch_set(scene.mesh).total_area / 1000;
            o.sequence = sequence;
            o.control_variate = cv;
            solve_on_one_and_two_threads(scene.mesh, o);
        }
    }
}

}  // namespace
}  // namespace hmcr::test
