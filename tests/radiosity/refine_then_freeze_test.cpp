// SPDX-License-Identifier: Apache-2.0
// Refine, then freeze (docs/design.md §3.10): the refining pass's mesh, the frozen pass's values,
// exact on the plates, and the same bits for any thread count and under a budget search.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/budget_search.h"
#include "radiosity/solve_passes.h"
#include "radiosity/solver.h"
#include "rays/embree_scene.h"
#include "tests/support/analytic.h"
#include "tests/support/plugins.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test::refine_then_freeze {
namespace {

std::vector<ElementId> leaf_ids(const Hierarchy& h) {
    std::vector<ElementId> ids;
    h.for_each_leaf([&](const Element& e) { ids.push_back(e.id); });
    return ids;
}

std::vector<float> leaf_values(const Hierarchy& h) {
    std::vector<float> v;
    h.for_each_leaf([&](const Element& e) {
        for (int c = 0; c < 3; ++c) v.push_back(float(e.radiosity[c]));
    });
    return v;
}

SolverOptions options(const char* oracle, std::uint64_t rays, double share) {
    SolverOptions o;
    o.oracle = test::oracle(oracle);
    o.rays = rays;
    o.seed = 4;
    o.lines = 4;
    o.refine_share = share;
    return o;
}

std::size_t frozen_iterations(const SolveStats& st) {
    const auto values = st.value_iterations();
    return !values.empty() && values.front().frozen ? values.size() : 0;
}

// The plates of solver_test (emitter rho = 0, E = 1; receiver rho = 0.5, 1 m above): only the
// frozen pass's first iteration reaches the receiver, its N_0 rays each hitting it with
// probability F, so the receiver's B = rho hits / N_0 is a binomial mean of rho F.
TEST(RefineThenFreeze, PlatesReceiverGetsRhoTimesEmissionTimesFormFactor) {
    const PatchMesh mesh = unit_plates(0.5);
    for (const char* oracle : {"power", "kl"}) {
        SolverOptions o = options(oracle, 400'000, 0.5);
        o.epsilon = 1e-3;
        const Solution sol = solve(mesh, o);
        ASSERT_GT(sol.stats.leaves, 2u) << oracle;
        ASSERT_GT(frozen_iterations(sol.stats), 0u) << oracle;
        const double f = parallel_rectangles(1, 1, 1);
        const double n0 = double(sol.stats.value_iterations().front().rays);
        const double se = 0.5 * std::sqrt(f * (1 - f) / n0);
        EXPECT_TRUE(within_standard_errors(std::string(oracle) + " receiver B",
                                           sol.hierarchy->root(1).radiosity[1], 0.5 * f, se));
    }
}

// The mesh is the one a refined solve with the refining share of the rays builds; the rays are
// both passes'; the oracle counts are the refining pass's.
TEST(RefineThenFreeze, TheMeshIsTheRefiningSharesAndTheRaysAreBothPasses) {
    const Scene scene = load_scene("cornell");
    const Solution both = solve(scene.mesh, options("kl", 400'000, 0.25));
    const Solution refined = solve(scene.mesh, options("kl", 100'000, 1));
    EXPECT_EQ(leaf_ids(*both.hierarchy), leaf_ids(*refined.hierarchy));
    EXPECT_EQ(both.stats.oracle_calls, refined.stats.oracle_calls);
    EXPECT_EQ(both.stats.refining_rays, refined.stats.rays);
    EXPECT_GT(frozen_iterations(both.stats), 0u);
    EXPECT_EQ(frozen_iterations(refined.stats), 0u);
    EXPECT_NEAR(double(both.stats.rays), 400'000.0, 0.02 * 400'000);
    EXPECT_NE(leaf_values(*both.hierarchy), leaf_values(*refined.hierarchy));
}

// A solve's statistics join its two passes' as radiosity/solver.h's table says: what built the
// mesh is the refining pass's, times and rays add, the rest is the frozen pass's own.
TEST(RefineThenFreeze, TheStatisticsJoinBothPasses) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = options("kl", 300'000, 0.25);
    o.importance = Importance::views;
    const Passes passes = passes_of(o);
    ShootingSetup shooting;
    Solution refined =
        refine_pass(build_patch_set(scene.mesh), o, passes.refining, {scene.views}, shooting);
    const SolveStats r = refined.stats;
    const Solution both = freeze_pass(std::move(refined), passes.frozen, std::move(shooting));
    const SolveStats& s = both.stats;
    ASSERT_GT(r.oracle_calls, 0u);
    ASSERT_GT(r.importance_rays, 0u);
    EXPECT_EQ(s.refining_rays, r.rays);
    EXPECT_EQ(s.rays, o.rays);
    EXPECT_EQ(s.oracle_calls, r.oracle_calls);
    EXPECT_EQ(s.oracle_evaluations, r.oracle_evaluations);
    EXPECT_EQ(s.cache_hits, r.cache_hits);
    EXPECT_EQ(s.lines_cast, r.lines_cast);
    EXPECT_EQ(s.oracle_seconds, r.oracle_seconds);
    EXPECT_EQ(s.cache_capacity, r.cache_capacity);
    EXPECT_EQ(s.importance_rays, r.importance_rays);
    EXPECT_EQ(s.importance_seconds, r.importance_seconds);
    EXPECT_EQ(s.epsilon, r.epsilon);
    EXPECT_EQ(s.refining_seconds, r.total_seconds);
    EXPECT_GT(s.total_seconds, r.total_seconds);
    EXPECT_GE(s.shooting_seconds, r.shooting_seconds);
    EXPECT_EQ(s.leaves, r.leaves);  // the same mesh
    EXPECT_EQ(s.patches, r.patches);
    ASSERT_GT(s.iterations.size(), r.iterations.size());
    for (std::size_t k = 0; k < s.iterations.size(); ++k) {
        EXPECT_EQ(s.iterations[k].frozen, k >= r.iterations.size()) << k;
        if (k < r.iterations.size()) {
            EXPECT_EQ(s.iterations[k].rays, r.iterations[k].rays) << k;
        }
    }
    // The power balance is the frozen pass's: its iterations' rays shot all of it.
    EXPECT_NE(channel_sum(s.shot_power), channel_sum(r.shot_power));
}

TEST(RefineThenFreeze, OneAndTwoThreadsGiveTheSameBits) {
    const Scene scene = load_scene("cornell");
    solve_on_one_and_two_threads(scene.mesh, options("power", 300'000, 0.5));
}

// View importance's adjoint solve and weights do not depend on the thread count either.
TEST(RefineThenFreeze, ViewImportanceGivesTheSameBitsOnOneAndTwoThreads) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = options("kl", 300'000, 0.5);
    o.importance = Importance::views;
    EXPECT_GT(solve_on_one_and_two_threads(scene.mesh, o, {scene.views}).stats.importance_rays, 0u);
}

// The frozen pass solves the refining pass's tree again in place: nothing the refining pass
// left in it reaches the frozen values. Two identical refining passes, one of them scribbled
// over in every element, freeze to the same bits, with clusters and without.
TEST(RefineThenFreeze, TheFrozenPassForgetsTheRefiningPassValues) {
    const Scene scene = load_scene("cornell");
    for (const Clustering clustering : {Clustering::none, Clustering::isotropic}) {
        SolverOptions o = options("kl", 200'000, 0.5);
        o.clustering = clustering;
        if (clustering == Clustering::isotropic) o.epsilon = 3;  // accepts links at clusters
        const Passes passes = passes_of(o);
        ShootingSetup clean_shooting, scribbled_shooting;
        Solution clean =
            refine_pass(build_patch_set(scene.mesh), o, passes.refining, {}, clean_shooting);
        Solution scribbled =
            refine_pass(build_patch_set(scene.mesh), o, passes.refining, {}, scribbled_shooting);
        scribbled.hierarchy->for_each_element([](Element& e) {
            e.radiosity = Rgb(3, 5, 7);
            e.unshot = Rgb(-1, 2, 0.5);
            e.received = {11, 13, 17};
        });
        const Solution a = freeze_pass(std::move(clean), passes.frozen, std::move(clean_shooting));
        const Solution b =
            freeze_pass(std::move(scribbled), passes.frozen, std::move(scribbled_shooting));
        ASSERT_GT(frozen_iterations(a.stats), 0u);
        expect_same_leaves(*a.hierarchy, *b.hierarchy);
        EXPECT_EQ(a.cluster_of_side(), b.cluster_of_side());
        if (clustering == Clustering::isotropic) {
            EXPECT_GT(a.stats.cluster_leaves, 0u);
        }
    }
}

// Embree's scene and the shooting buffers are made once for both passes, and for every probe of
// a budget search: the refining pass leaves them in its ShootingSetup for the next probe and the
// frozen pass, which lets them go (a Solution holds none: the scene is most of a large scene's
// memory after the patches).
TEST(RefineThenFreeze, ThePassesShareOneSceneAndTheFrozenPassLetsItGo) {
    const Scene scene = load_scene("cornell");
    const SolverOptions o = options("kl", 100'000, 0.5);
    const Passes passes = passes_of(o);
    ShootingSetup shooting;
    Solution refined = refine_pass(build_patch_set(scene.mesh), o, passes.refining, {}, shooting);
    ASSERT_TRUE(shooting.scene);
    ASSERT_TRUE(shooting.buffers);
    const std::weak_ptr<const EmbreeScene> kept = shooting.scene;
    const std::weak_ptr<ShootingBuffers> kept_buffers = shooting.buffers;
    // A probe given them shoots with them and leaves them as they were.
    ShootingSetup probe = shooting;
    refine_pass(build_patch_set(scene.mesh), o, passes.refining, {}, probe);
    EXPECT_EQ(probe.scene, shooting.scene);
    EXPECT_EQ(probe.buffers, shooting.buffers);
    probe = {};
    const Solution frozen = freeze_pass(std::move(refined), passes.frozen, std::move(shooting));
    ASSERT_GT(frozen_iterations(frozen.stats), 0u);
    EXPECT_EQ(kept.use_count(), 0);
    EXPECT_EQ(kept_buffers.use_count(), 0);
}

// The two passes split the rays by the share, at least one each, and both take the oracle's
// threshold where the options give none; a solve that does not refine then freeze is one pass.
TEST(RefineThenFreeze, ThePassesSplitTheRaysOnce) {
    SolverOptions o = options("kl", 1000, 0.25);
    o.epsilon = kOracleDefault;
    const Passes passes = passes_of(o);
    EXPECT_EQ(passes.refining.rays, 250u);
    EXPECT_EQ(passes.frozen.rays, 750u);
    EXPECT_EQ(passes.refining.epsilon, o.oracle->default_epsilon());
    EXPECT_EQ(passes.frozen.epsilon, o.oracle->default_epsilon());
    o.refine_share = 1;
    EXPECT_EQ(passes_of(o).refining.rays, 1000u);
    EXPECT_EQ(passes_of(o).frozen.rays, 0u);
    o.refine_share = 0.5;
    o.rays = 1;
    EXPECT_EQ(passes_of(o).frozen.rays, 0u);
}

// A reference's uniform mesh has nothing to refine: every ray solves it, whatever the share.
TEST(RefineThenFreeze, AUniformMeshIgnoresTheShare) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = options("power", 100'000, 0.1);
    o.uniform_max_area = 0.01;
    const Solution shared = solve(scene.mesh, o);
    o.refine_share = 1;
    const Solution whole = solve(scene.mesh, o);
    EXPECT_EQ(frozen_iterations(shared.stats), 0u);
    EXPECT_EQ(shared.stats.iterations.size(), whole.stats.iterations.size());
    expect_same_leaves(*shared.hierarchy, *whole.hierarchy);
}

// Patches that nothing may split (max_depth 0, no clusters) are a fixed mesh too: every ray
// solves them on the leaf lookup, whatever the share, so that lines go both ways in all of
// them; with clusters to open the share still refines them.
TEST(RefineThenFreeze, UnsplittablePatchesIgnoreTheShare) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = options("power", 100'000, 0.1);
    o.max_depth = 0;
    o.bidirectional = Bidirectional::yes;
    const Solution shared = solve(scene.mesh, o);
    o.refine_share = 1;
    const Solution whole = solve(scene.mesh, o);
    EXPECT_EQ(frozen_iterations(shared.stats), 0u);
    EXPECT_EQ(shared.stats.oracle_evaluations, 0u);  // no descent asks the oracle
    EXPECT_EQ(shared.stats.rays, 100'000u);
    expect_same_leaves(*shared.hierarchy, *whole.hierarchy);
    o.bidirectional = Bidirectional::no;
    const Solution one_way = solve(scene.mesh, o);
    EXPECT_NE(leaf_values(*one_way.hierarchy), leaf_values(*whole.hierarchy));
    o.clustering = Clustering::isotropic;
    o.refine_share = 0.1;
    EXPECT_GT(passes_of(o).frozen.rays, 0u);
}

// A budget search probes with the refining pass and freezes the accepted probe: its leaves are
// within the tolerance and those of the same search with the refining share of the rays.
TEST(RefineThenFreeze, ABudgetSearchFreezesTheAcceptedProbe) {
    Scene scene = load_scene("cornell");
    const BudgetOptions budget{.leaves = 3000, .tolerance = 0.02};
    const BudgetResult both = solve_for_budget(scene.mesh, options("power", 400'000, 0.5), budget);
    const BudgetResult refined = solve_for_budget(scene.mesh, options("power", 200'000, 1), budget);
    const Solution& s = both.solution;
    EXPECT_LE(std::abs(double(s.stats.leaves) - 3000.0), 0.02 * 3000);
    EXPECT_EQ(leaf_ids(*s.hierarchy), leaf_ids(*refined.solution.hierarchy));
    EXPECT_EQ(both.probes.size(), refined.probes.size());
    EXPECT_GT(frozen_iterations(s.stats), 0u);
    EXPECT_NEAR(double(s.stats.rays), 400'000.0, 0.02 * 400'000);
}

// The probes of a budget search share one importance solve: the accepted probe's mesh is the
// one a solve at its epsilon makes with an importance solve of its own.
TEST(RefineThenFreeze, ABudgetSearchSharesItsViewImportance) {
    Scene scene = load_scene("cornell");
    SolverOptions o = options("power", 200'000, 0.5);
    o.importance = Importance::views;
    const BudgetResult found =
        solve_for_budget(scene.mesh, o, {.leaves = 3000, .tolerance = 0.02}, {scene.views});
    ASSERT_GT(found.probes.size(), 1u);
    o.epsilon = found.solution.stats.epsilon;
    const Solution alone = solve(scene.mesh, o, {scene.views});
    expect_same_leaves(*found.solution.hierarchy, *alone.hierarchy);
    EXPECT_EQ(found.solution.stats.importance_rays, alone.stats.importance_rays);
}

}  // namespace
}  // namespace hmcr::test::refine_then_freeze
