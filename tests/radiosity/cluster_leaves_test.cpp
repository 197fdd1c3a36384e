// SPDX-License-Identifier: Apache-2.0
// Clusters as leaves of the mesh (docs/design.md §2.7): budgets below the patch count, the
// frozen pass depositing on cluster leaves, what the mesh counts and what the output says of
// each face's cluster, with results that stay exact: the furnace per patch, a shadow's umbra
// dark, the same bits for one and two threads.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "radiosity/budget_search.h"
#include "radiosity/clusters.h"
#include "radiosity/shaded_mesh.h"
#include "radiosity/solver.h"
#include "tests/support/cluster_models.h"
#include "tests/support/furnace.h"
#include "tests/support/plugins.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

SolverOptions with_cluster_leaves(std::uint64_t rays, std::uint64_t seed,
                                  Clustering model = Clustering::isotropic) {
    SolverOptions o;
    o.clustering = model;
    o.rays = rays;
    o.seed = seed;
    o.lines = 4;
    return o;
}

PatchMesh furnace_of(int n) {
    return make_patch_mesh(
        inward_box({0, 0, 0}, {1, 1, 1}, n, Rgb::Constant(0.5), Rgb::Constant(1)));
}

// The mesh's leaf count is its cluster leaves and the faces outside them; every face under a
// cluster leaf is a patch's unsplit side, and the faces of one cluster leaf are its own.
void expect_consistent_mesh(const Solution& sol) {
    ShadedMesh cells = build_shaded_mesh(*sol.hierarchy);
    set_cluster_ids(cells, sol.cluster_of_side());
    ASSERT_EQ(cells.cluster_id.size(), cells.cell_count());
    std::set<std::int32_t> clusters;
    std::size_t outside = 0;
    for (std::size_t c = 0; c < cells.cell_count(); ++c) {
        if (cells.cluster_id[c] < 0) {
            ++outside;
            continue;
        }
        clusters.insert(cells.cluster_id[c]);
        EXPECT_EQ(cells.hierarchy_level[c], 0) << "cell " << c;
    }
    EXPECT_EQ(clusters.size(), sol.stats.cluster_leaves);
    EXPECT_EQ(outside + clusters.size(), sol.stats.leaves);
    EXPECT_EQ(cells.cell_count(), sol.stats.faces);
}

// A budget below the patch count is reached with clusters as leaves, and the search's solution
// (refined, then frozen) has the mesh it counted.
TEST(ClusterLeaves, BudgetBelowThePatchCountIsReached) {
    const PatchMesh mesh = furnace_of(16);  // 1,536 patches
    const BudgetResult r =
        solve_for_budget(mesh, with_cluster_leaves(200'000, 5), BudgetOptions{.leaves = 400});
    const SolveStats& st = r.solution.stats;
    EXPECT_NEAR(double(st.leaves), 400, 4);
    EXPECT_GT(st.cluster_leaves, 0u);
    EXPECT_TRUE(st.iterations.back().frozen);  // a guard: the frozen pass ran on it
    expect_consistent_mesh(r.solution);
    // Without clusters the same budget is refused, saying why.
    SolverOptions none = with_cluster_leaves(200'000, 5);
    none.clustering = Clustering::none;
    try {
        solve_for_budget(mesh, none, BudgetOptions{.leaves = 400});
        ADD_FAILURE() << "a budget below the patch count without clusters was not refused";
    } catch (const BudgetNotReached& e) {
        EXPECT_NE(std::string(e.what()).find("--clustering oriented"), std::string::npos)
            << e.what();
    }
}

// The furnace refined to cluster leaves and frozen: every patch's B is the exact K-bounce value
// E (1 - rho^(K+1)) / (1 - rho) (K the frozen pass's iterations), t-tested over 10 seeds with
// Bonferroni over the patches: a deposit on a cluster leaf gives its patches the irradiance
// it carries, which in the furnace is every patch's; an oriented one gives each class of its
// sides the part of each ray's power they face, which in the convex furnace is their due.
class ClusterLeafModels : public testing::TestWithParam<Clustering> {};
INSTANTIATE_TEST_SUITE_P(ClusterLeaves, ClusterLeafModels, cluster_models(), cluster_model_name);

TEST_P(ClusterLeafModels, FurnaceFrozenOnClusterLeavesIsExact) {
    const PatchMesh mesh = furnace_of(12);  // 864 patches
    expect_furnace_per_patch(
        mesh, 0.5, 1, 10,
        [](std::uint64_t seed) {
            SolverOptions o = with_cluster_leaves(40'000, seed, GetParam());
            o.epsilon = 3;  // accepts links at clusters (a guard below)
            return o;
        },
        [&](const Solution& sol) {
            EXPECT_GT(sol.stats.cluster_leaves, 0u) << "seed " << sol.options.seed;
            EXPECT_LT(sol.stats.leaves, mesh.n_faces()) << "seed " << sol.options.seed;
        });
}

// scenes/shadow with its floor cut into 40 x 40 patches of 0.05 m: the umbra is
// max(|x|, |y|) <= 0.2667 m, so the 10 x 10 patches within 0.25 m of the axis never receive
// light, and the floor beyond 0.4 m sees the whole emitter. A cluster leaf spreads what it
// receives over all its sides (docs/design.md §2.7), so the clusters over the floor must split
// where the shadow is: no cluster leaf may hold an umbra patch and a patch of the fully lit
// floor or the occluder (whose top is lit), and an umbra patch whose cluster leaf holds umbra
// patches alone (or that is in the mesh itself) stays exactly dark. Only a leaf shared with the
// penumbra's weak light may light the umbra. Three seeds; guards: cluster leaves exist, fewer
// leaves than patches, most umbra patches are checked, the lit floor is lit.
TEST(ClusterLeaves, ShadowsSplitTheClusters) {
    std::vector<TestPolygon> polygons;
    const int n = 40;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double s = 2.0 / n;
            TestPolygon tile = axis_rectangle(2, 0, {-1 + i * s, -1 + j * s},
                                              {-1 + (i + 1) * s, -1 + (j + 1) * s}, true);
            tile.reflectance = Rgb::Constant(0.5);
            polygons.push_back(tile);
        }
    }
    TestPolygon emitter = axis_rectangle(2, 1.5, {-0.1, -0.1}, {0.1, 0.1}, false);
    emitter.emission = Rgb::Constant(M_PI);
    polygons.push_back(emitter);
    polygons.push_back(axis_rectangle(2, 0.6, {-0.2, -0.2}, {0.2, 0.2}, true));
    const std::size_t occluder = polygons.size() - 1;
    const PatchMesh mesh = make_patch_mesh(polygons);
    enum Kind { umbra, penumbra, lit, other };
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        SolverOptions o = with_cluster_leaves(400'000, seed);
        o.lines = 10;
        o.epsilon = 1e-5;
        const Solution sol = solve(mesh, o);
        EXPECT_GT(sol.stats.cluster_leaves, 0u) << "seed " << seed;
        EXPECT_LT(sol.stats.leaves, polygons.size()) << "seed " << seed;
        const auto kind = [&](std::size_t p) {
            if (p >= std::size_t(n * n)) return p == occluder ? lit : other;
            const Vec3& c = sol.hierarchy->root(p).centre;
            const double r = std::max(std::abs(c.x()), std::abs(c.y()));
            return r < 0.25 ? umbra : r > 0.425 ? lit : penumbra;
        };
        std::map<std::int32_t, std::set<Kind>> kinds;  // of each cluster leaf's patches
        for (std::size_t p = 0; p < polygons.size(); ++p) {
            kinds[sol.cluster_of_side()[2 * p]].insert(kind(p));
        }
        std::size_t dark = 0;
        double lit_power = 0;
        for (std::size_t p = 0; p < std::size_t(n * n); ++p) {
            const std::int32_t c = sol.cluster_of_side()[2 * p];
            const double b = sol.hierarchy->root(p).radiosity[1];
            if (kind(p) == lit) lit_power += b;
            if (kind(p) != umbra || c < 0) continue;
            EXPECT_EQ(kinds[c].count(lit), 0u) << "seed " << seed << " cluster " << c;
            if (kinds[c].size() == 1) {
                EXPECT_EQ(b, 0.0) << "seed " << seed << " patch " << p;
                ++dark;
            }
        }
        for (std::size_t p = 0; p < std::size_t(n * n); ++p) {
            if (kind(p) == umbra && sol.cluster_of_side()[2 * p] < 0) {
                EXPECT_EQ(sol.hierarchy->root(p).radiosity[1], 0.0) << "seed " << seed;
                ++dark;
            }
        }
        EXPECT_GE(dark, 50u) << "seed " << seed;
        EXPECT_GT(lit_power, 0.0) << "seed " << seed;
    }
}

// The control variate on a frozen mesh with cluster leaves (docs/design.md §3.11): a closed box
// whose walls emit 1 or 2, solved with and without it on the same refined mesh (the seed's);
// a uniform radiosity beta lights every point of a closed box with an irradiance beta, so a
// cluster leaf's patches get rho beta from the shots it replaces, as the control variate adds:
// the same expectation (paired t test of a patch's B over 16 seeds). Guards: cluster leaves
// and a nonzero beta.
TEST(ClusterLeaves, TheControlVariateKeepsTheExpectation) {
    std::vector<TestPolygon> box =
        inward_box({0, 0, 0}, {1, 1, 1}, 8, Rgb::Constant(0.5), Rgb::Constant(1));
    for (std::size_t p = 0; p < box.size() / 2; ++p) box[p].emission = Rgb::Constant(2);
    const PatchMesh mesh = make_patch_mesh(box);
    std::vector<double> difference;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        SolverOptions o = with_cluster_leaves(20'000, seed);
        o.epsilon = 3;
        o.control_variate = ControlVariate::constant;
        const Solution cv = solve(mesh, o);
        o.control_variate = ControlVariate::none;
        const Solution plain = solve(mesh, o);
        ASSERT_GT(cv.stats.cluster_leaves, 0u) << "seed " << seed;
        ASSERT_EQ(cv.cluster_of_side(), plain.cluster_of_side()) << "seed " << seed;
        EXPECT_NE(cv.stats.value_iterations()[0].control_constant[0], 0.0);
        const std::size_t patch = box.size() - 1;  // an emitter of 1
        difference.push_back(cv.hierarchy->root(patch).radiosity[0] -
                             plain.hierarchy->root(patch).radiosity[0]);
    }
    EXPECT_TRUE(t_test("B with minus B without", difference, 0));
}

// The same seed gives the same mesh, cluster leaves and values with one thread and with two.
TEST_P(ClusterLeafModels, OneAndTwoThreadsGiveTheSameBits) {
    SolverOptions o = with_cluster_leaves(100'000, 3, GetParam());
    o.epsilon = 3;
    EXPECT_GT(solve_on_one_and_two_threads(furnace_of(8), o).stats.cluster_leaves, 0u);
}

// A mesh frozen from a clustered solve (a study's mesh error) keeps its cluster leaves and how
// they receive.
TEST_P(ClusterLeafModels, SolveOnMeshKeepsTheClusterLeaves) {
    const PatchMesh mesh = furnace_of(8);
    SolverOptions o = with_cluster_leaves(60'000, 4, GetParam());
    o.epsilon = 3;
    o.refine_share = 1;
    const Solution shape = solve(mesh, o);
    ASSERT_GT(shape.stats.cluster_leaves, 0u);
    o.rays = 30'000;
    const Solution frozen = solve_on_mesh(mesh, o, shape);
    EXPECT_EQ(frozen.cluster_of_side(), shape.cluster_of_side());
    EXPECT_EQ(frozen.stats.leaves, shape.stats.leaves);
    ASSERT_NE(frozen.clusters, nullptr);
    EXPECT_EQ(frozen.clusters->model(), GetParam());
    expect_consistent_mesh(frozen);
}

}  // namespace
}  // namespace hmcr::test
