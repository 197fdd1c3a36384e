// SPDX-License-Identifier: Apache-2.0
// Two-sided patches against exact results (docs/design.md §1.3, §8): each side has its own
// material, radiosity and elements, and a one-sided patch keeps a black, absorbing back.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "radiosity/solver.h"
#include "tests/support/analytic.h"
#include "tests/support/plugins.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

SolverOptions options(std::uint64_t rays, std::uint64_t seed) {
    SolverOptions o;
    o.oracle = test::oracle("power");
    o.rays = rays;
    o.seed = seed;
    return o;
}

// Unit squares 1 m apart: emitter A (E = 1) at z = 0 facing up, a two-sided plate at z = 1
// whose front faces A (rho 0.5) and whose back (rho 0.25) faces emitter B (E = 2) at z = 2.
// Emitters are black, so only the first iteration lights the plate: every ray carries S / N,
// S = 3 W, and hits the front from A with probability F / 3, the back from B with 2F / 3.
std::vector<TestPolygon> plate_between_emitters() {
    TestPolygon a = axis_rectangle(2, 0, {0, 0}, {1, 1}, true);
    a.emission = Rgb::Constant(1);
    TestPolygon plate = axis_rectangle(2, 1, {0, 0}, {1, 1}, false);
    plate.reflectance = Rgb::Constant(0.5);
    plate.two_sided = true;
    plate.back_reflectance = Rgb::Constant(0.25);
    TestPolygon b = axis_rectangle(2, 2, {0, 0}, {1, 1}, false);
    b.emission = Rgb::Constant(2);
    return {a, plate, b};
}

TEST(TwoSided, EachSideOfAPlateGetsTheLightOfTheEmitterItFaces) {
    const Solution sol = solve(make_patch_mesh(plate_between_emitters()), options(600'000, 5));
    const double f = parallel_rectangles(1, 1, 1),
                 n0 = double(sol.stats.value_iterations()[0].rays);
    const Hierarchy& h = *sol.hierarchy;
    ASSERT_NE(h.back_root(1), nullptr);
    EXPECT_EQ(h.back_root(0), nullptr);  // one-sided: no back
    struct Side {
        const char* name;
        const Element& root;
        double rho, emission;
    };
    for (const Side& s :
         {Side{"front", h.root(1), 0.5, 1.0}, Side{"back", *h.back_root(1), 0.25, 2.0}}) {
        const double p = s.emission * f / 3;  // the chance that a ray lands on this side
        const double se = s.rho * 3 * std::sqrt(p * (1 - p) / n0);
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(within_standard_errors(std::string(s.name) + " B", s.root.radiosity[c],
                                               s.rho * s.emission * f, se));
        }
    }
    // No ray meets a back it cannot take: the plate takes both of its sides' light.
    EXPECT_EQ(sol.stats.back_face_power.sum(), 0);
}

// A closed furnace of two-sided walls whose inner sides emit E = 1 with rho = 0.5 and whose
// outer sides emit 0.3 into the void: inside B = E (1 - rho^(K+1)) / (1 - rho) as for one-sided
// walls, outside exactly 0.3 (nothing reaches it: rays from outside escape).
TEST(TwoSided, FurnaceInsideTwoSidedWallsAndTheirOuterSides) {
    std::vector<TestPolygon> walls =
        inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Constant(1));
    for (TestPolygon& w : walls) {
        w.two_sided = true;
        w.back_reflectance = Rgb::Constant(0.5);
        w.back_emission = Rgb::Constant(0.3);
    }
    const auto mesh = make_patch_mesh(walls);
    std::vector<std::vector<double>> inside(mesh.n_faces());
    std::size_t iterations = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        SolverOptions o = options(30'000, seed);
        o.max_depth = 0;
        const Solution sol = solve(mesh, o);
        if (seed > 1) {
            ASSERT_EQ(sol.stats.value_iterations().size(), iterations) << "seed " << seed;
        }
        iterations = sol.stats.value_iterations().size();
        for (std::size_t p = 0; p < mesh.n_faces(); ++p) {
            inside[p].push_back(sol.hierarchy->root(p).radiosity[1]);
            const Element* out = sol.hierarchy->back_root(p);
            ASSERT_NE(out, nullptr);  // it emits: a source from the start
            EXPECT_EQ(out->radiosity[1], 0.3) << "outer side of wall " << p;
        }
    }
    // The outer sides' power escapes, and the stop rule counts the inside's alone.
    const double expected = (1 - std::pow(0.5, double(iterations + 1))) / (1 - 0.5);
    for (std::size_t p = 0; p < inside.size(); ++p) {
        EXPECT_TRUE(t_test("inner side of wall " + std::to_string(p), inside[p], expected, 0,
                           int(inside.size())));
    }
}

// A mesh that carries back materials but where every face is one-sided solves to the same bits
// as one without them.
TEST(TwoSided, OneSidedFacesWithTheBackPropertyGiveTheSameBits) {
    std::vector<TestPolygon> polys = plate_between_emitters();
    polys[1].two_sided = false;
    const PatchMesh plain = make_patch_mesh(polys);
    PatchMesh marked = make_patch_mesh(polys);
    auto back = back_material_prop(marked);
    for (auto f : marked.faces()) back[f] = kOneSided;
    expect_same_leaves(*solve(plain, options(100'000, 3)).hierarchy,
                       *solve(marked, options(100'000, 3)).hierarchy);
}

TEST(TwoSided, SameHierarchyAndValuesForOneAndTwoThreads) {
    const PatchMesh mesh = make_patch_mesh(plate_between_emitters());
    SolverOptions o = options(200'000, 9);
    o.oracle = test::oracle("kl");
    const Solution one = solve_on_one_and_two_threads(mesh, o);
    std::size_t backs = 0;
    one.hierarchy->for_each_leaf([&](const Element& e) { backs += e.id.side == kBack; });
    EXPECT_GT(backs, 10u);  // the back refined too
}

}  // namespace
}  // namespace hmcr::test
