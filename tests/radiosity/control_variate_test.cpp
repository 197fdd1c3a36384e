// SPDX-License-Identifier: Apache-2.0
// The constant control variate (docs/design.md §3.11): exact where the plain estimator is
// exact, the same expected values, less spread where the unshot radiosity is nearly constant,
// and the same bits for any thread count.
#include "radiosity/control_variate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/solver.h"
#include "tests/support/analytic.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

SolverOptions fixed_mesh(std::uint64_t rays, std::uint64_t seed, double max_area) {
    SolverOptions o;
    o.rays = rays;
    o.seed = seed;
    o.uniform_max_area = max_area;
    o.control_variate = ControlVariate::constant;
    return o;
}

// The furnace: every surface emits E and reflects rho, so Delta B is the same everywhere in
// every iteration; beta is that value, nothing is left to shoot, and rho beta is added exactly:
// B = E (1 - rho^(K+1)) / (1 - rho) after K iterations on every leaf, to rounding, for every
// seed.
TEST(ControlVariate, FurnaceIsExact) {
    const double rho = 0.5, e = 1;
    const auto mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(rho), Rgb::Constant(e)));
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const Solution sol = solve(mesh, fixed_mesh(30'000, seed, 1.0 / 64));
        const double k = double(sol.stats.iterations.size());
        const double expected = e * (1 - std::pow(rho, k + 1)) / (1 - rho);
        EXPECT_NEAR(expected, e / (1 - rho), 0.01 * e / (1 - rho));
        EXPECT_EQ(sol.stats.rays, 0u);  // nothing was left to shoot
        sol.hierarchy->for_each_leaf([&](const Element& leaf) {
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(leaf.radiosity[c], expected, 1e-12);
        });
    }
}

// A closed box whose faces emit 1 or 2: the plain estimator and the control variate have the
// same expected values (paired t test of one patch's B over seeds, and the exact total), and
// the control variate's spread is smaller (F test), since it shoots about a third of the power.
TEST(ControlVariate, SameExpectationLessSpreadInAClosedBox) {
    std::vector<TestPolygon> box =
        inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(0.5), Rgb::Constant(1));
    for (std::size_t p = 0; p < box.size() / 2; ++p) box[p].emission = Rgb::Constant(2);
    const auto mesh = make_patch_mesh(box);
    std::vector<double> with, without, difference;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        SolverOptions o = fixed_mesh(20'000, seed, 1.0 / 64);
        const Solution cv = solve(mesh, o);
        o.control_variate = ControlVariate::none;
        const Solution plain = solve(mesh, o);
        ASSERT_EQ(cv.stats.iterations.size(), plain.stats.iterations.size());
        EXPECT_NE(cv.stats.iterations[0].control_constant[0], 0.0);
        const std::size_t patch = box.size() - 1;  // an emitter of 1
        with.push_back(cv.hierarchy->root(patch).radiosity[0]);
        without.push_back(plain.hierarchy->root(patch).radiosity[0]);
        difference.push_back(with.back() - without.back());
    }
    EXPECT_TRUE(t_test("B with minus B without", difference, 0));
    EXPECT_TRUE(variance_smaller("spread of B over seeds", with, without));
}

// The plates of solver_test (emitter rho = 0, E = 1; receiver rho = 0.5, 1 m above, B = rho E F):
// the open bounding box outweighs the lit area, so beta is 0 in every iteration and the solve
// is the plain one, bit for bit, with its exact expectation.
TEST(ControlVariate, PlatesKeepThePlainIterations) {
    const auto mesh = unit_plates(0.5);
    SolverOptions o = fixed_mesh(50'000, 4, 1.0 / 16);
    const Solution cv = solve(mesh, o);
    o.control_variate = ControlVariate::none;
    const Solution plain = solve(mesh, o);
    for (const IterationRecord& it : cv.stats.iterations)
        EXPECT_TRUE((it.control_constant == 0).all());
    expect_same_leaves(*cv.hierarchy, *plain.hierarchy);
}

// Open: two parallel unit plates 0.1 m apart, two-sided, both sides emitting 1 and reflecting
// 0.5, fronts facing each other. Each front sees the other with F and the background with
// 1 - F; each back sees only the background. After n iterations a front holds
// E sum_{k<=n} (rho F)^k, a back E. The first iteration's beta is E (the sides outweigh the
// open faces of the bounding box), so the background's -beta rays make the exact total.
TEST(ControlVariate, OpenTwoSidedPlates) {
    const double rho = 0.5, e = 1, d = 0.1;
    auto plate = [&](double z, bool up) {
        TestPolygon p = axis_rectangle(2, z, {0, 0}, {1, 1}, up);
        p.reflectance = p.back_reflectance = Rgb::Constant(rho);
        p.emission = p.back_emission = Rgb::Constant(e);
        p.two_sided = true;
        return p;
    };
    const auto mesh = make_patch_mesh({plate(0, true), plate(d, false)});
    const double f = parallel_rectangles(1, 1, d);
    std::vector<double> front, back;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const Solution sol = solve(mesh, fixed_mesh(100'000, seed, 1.0));
        EXPECT_EQ(sol.stats.iterations[0].control_constant[1], e);
        const double n = double(sol.stats.iterations.size());
        const double expected = e * (1 - std::pow(rho * f, n + 1)) / (1 - rho * f);
        for (std::size_t p = 0; p < 2; ++p) {
            front.push_back(sol.hierarchy->root(p).radiosity[1] - expected);
            back.push_back(sol.hierarchy->root(p, kBack).radiosity[1] - e);
        }
    }
    EXPECT_TRUE(t_test("front B minus exact", front, 0, 0, 2));
    EXPECT_TRUE(t_test("back B minus exact", back, 0, 0, 2));
}

// The Cornell box's open side is background, its walls' backs are not seen: the same leaves
// and values, bit for bit, with 1 and 2 threads.
// A shifted iteration's powers are signed sums of Delta B - beta and -beta: the summary's
// balance keeps the iterations that shot the unshot power itself, so on the Cornell box (open
// at the front, no flipped faces) the shot power is the first iteration's emitted power at least,
// and the escaped and back-face shares stay the plain solve's kind of numbers.
TEST(ControlVariate, ThePowerBalanceKeepsThePlainIterations) {
    const Scene scene = load_scene("cornell");
    const Solution sol = solve(scene.mesh, fixed_mesh(400'000, 2, 1e-3));
    bool shifted = false;
    for (const IterationRecord& it : sol.stats.iterations)
        shifted |= (it.control_constant != 0).any();
    ASSERT_TRUE(shifted);
    EXPECT_GE(sol.stats.shot_power.sum(), 0.99 * sol.stats.emitted_power.sum());
    EXPECT_GT(sol.stats.escaped_power.minCoeff(), 0);
    EXPECT_GE(sol.stats.back_face_fraction(), 0);
    EXPECT_LT(sol.stats.back_face_fraction(), 0.01);
}

TEST(ControlVariate, SameBitsForOneAndTwoThreads) {
    const Scene scene = load_scene("cornell");
    // With the Sobol sequence too: the zero surfaces' rays are dealt to them apart.
    for (const RaySequence sequence : {RaySequence::random, RaySequence::sobol}) {
        SolverOptions o = fixed_mesh(60'000, 3, 0.0);
        o.uniform_max_area = build_patch_set(scene.mesh).total_area / 1000;
        o.min_area = 0;
        o.sequence = sequence;
        const Solution one = solve_on_one_and_two_threads(scene.mesh, o);
        bool shifted = false;
        for (const IterationRecord& it : one.stats.iterations)
            shifted |= (it.control_constant != 0).any();
        EXPECT_TRUE(shifted);
    }
}

// The zero surfaces: a closed box has none; an open one its open faces; the back of a
// one-sided patch counts where a reflecting side faces it.
TEST(ControlVariate, ZeroSurfaces) {
    const auto closed =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1)));
    const ZeroSurfaces none(build_patch_set(closed));
    EXPECT_FALSE(none.has_background());
    EXPECT_TRUE(none.backs.empty());
    std::vector<TestPolygon> open =
        inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1));
    open.pop_back();  // one face missing
    // A one-sided plate inside, facing up: the floor sees its back.
    TestPolygon plate = axis_rectangle(2, 0.5, {0.25, 0.25}, {0.75, 0.75}, true);
    plate.reflectance = Rgb::Constant(0.5);
    open.push_back(plate);
    const ZeroSurfaces some(build_patch_set(make_patch_mesh(open)));
    EXPECT_EQ(some.patches.size(), some.scene_patches + 1);
    ASSERT_EQ(some.backs.size(), 1u);
    EXPECT_EQ(some.backs[0], some.scene_patches - 1);
    EXPECT_NEAR(some.area, 1.0 + 0.25, 1e-9);
}

}  // namespace
}  // namespace hmcr::test
