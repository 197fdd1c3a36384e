// SPDX-License-Identifier: Apache-2.0
// Clusters (docs/design.md §2.7): the tree over the patches, the descent through it (grouped
// and one ray at a time alike), and exact results with clustering on: the furnace of many
// patches, the plates' form factor, and the same bits for one and two threads.
#include "radiosity/clusters.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <set>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/oracle_registry.h"
#include "radiosity/refinement.h"
#include "radiosity/solver.h"
#include "rays/embree_scene.h"
#include "rays/rng.h"
#include "tests/support/analytic.h"
#include "tests/support/cluster_models.h"
#include "tests/support/furnace.h"
#include "tests/support/plugins.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// Every side of a patch is reached from the top by child_toward, through clusters whose areas
// are their sides' sums, ending on that side's root.
void expect_every_side_reachable(Hierarchy& h, const ClusterTree& t) {
    EXPECT_NEAR(t.top().area, h.patch_set().total_area, 1e-12 * h.patch_set().total_area);
    for (std::uint32_t p = 0; p < h.patch_count(); ++p) {
        for (std::uint8_t side = kFront; side <= (h.patch_set().two_sided(p) ? kBack : kFront);
             ++side) {
            const Element* e = &t.top();
            int depth = 0;
            while (is_cluster(*e)) {
                const Element& next = t.child_toward(*e, 2 * p + side);
                ASSERT_LT(next.area, e->area);
                e = &next;
                ASSERT_LT(++depth, 64);
            }
            EXPECT_EQ(e, &h.root(p, side));
        }
    }
}

TEST(Clusters, TreeHoldsEverySideOnce) {
    Hierarchy box(build_patch_set(make_patch_mesh(
                      inward_box({0, 0, 0}, {1, 2, 3}, 5, Rgb::Constant(0.5), Rgb::Constant(1)))),
                  {});
    const ClusterTree tree(box);
    EXPECT_EQ(tree.size(), box.patch_count() - 1);
    expect_every_side_reachable(box, tree);
    // Two-sided patches: a tree over the fronts, one over the backs, and the top joining them,
    // the only cluster holding a front and a back, which never receives.
    std::vector<TestPolygon> walls =
        inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(0.5), Rgb::Constant(1));
    for (std::size_t k = 0; k < walls.size(); k += 3) walls[k].two_sided = true;
    Hierarchy sided(build_patch_set(make_patch_mesh(walls)), {});
    const ClusterTree sided_tree(sided);
    EXPECT_EQ(sided_tree.size(), sided.patch_count() - 1 + 8);
    expect_every_side_reachable(sided, sided_tree);
    const Element& top = sided_tree.top();
    EXPECT_FALSE(sided_tree.may_receive(top));
    for (std::uint32_t p = 0; p < sided.patch_count(); p += 3) {
        EXPECT_NE(&sided_tree.child_toward(top, 2 * p), &sided_tree.child_toward(top, 2 * p + 1));
    }
    EXPECT_TRUE(tree.may_receive(tree.top()));
}

// A cluster receiver's weight is the area-weighted mean of its sides': their reflectances, or
// the receiver weights view importance gives (docs/design.md §2.7).
TEST(Clusters, ReceiverWeightIsTheAreaWeightedMeanOfItsSides) {
    std::vector<TestPolygon> plates = {axis_rectangle(2, 0, {0, 0}, {1, 1}, true),
                                       axis_rectangle(2, 1, {0, 0}, {3, 1}, false)};
    plates[0].reflectance = Rgb::Constant(0.2);
    plates[1].reflectance = Rgb::Constant(0.6);
    Hierarchy h(build_patch_set(make_patch_mesh(plates)), {});
    const ClusterTree plain(h);
    EXPECT_NEAR(plain.receiver_weight(plain.top())[0], (0.2 * 1 + 0.6 * 3) / 4, 1e-15);
    const std::vector<Rgb> weights = {Rgb::Constant(2), Rgb::Zero(), Rgb::Constant(0.5),
                                      Rgb::Zero()};
    const ClusterTree weighted(h, weights);
    EXPECT_NEAR(weighted.receiver_weight(weighted.top())[0], (2 * 1 + 0.5 * 3) / 4.0, 1e-15);
}

// The tree depends on the patches alone: built twice, the same clusters.
TEST(Clusters, TreeIsDeterministic) {
    const PatchSet ps = build_patch_set(load_scene("cornell").mesh);
    Hierarchy a(ps, {}), b(ps, {});
    ClusterTree x(a), y(b);
    std::vector<double> areas;
    x.for_each_cluster([&](const Element& c) { areas.push_back(c.area); });
    std::size_t k = 0;
    y.for_each_cluster([&](const Element& c) {
        EXPECT_EQ(c.area, areas[k]);
        ++k;
    });
    EXPECT_EQ(k, areas.size());
}

// A point of a cluster lies on one of its sides, each side chosen in proportion to its area.
TEST(Clusters, PointsAreUniformByArea) {
    Hierarchy h(build_patch_set(load_scene("cornell").mesh), {});
    const ClusterTree t(h);
    const Element& top = t.top();
    Rng rng(3, 4);
    const int n = 20'000;
    double floor_hits = 0;  // the floor: the sides facing +y at y = 0
    for (int k = 0; k < n; ++k) {
        const auto [x, normal] = t.point(top, rng.uniform(), rng.uniform());
        if (normal.y() > 0.99 && std::abs(x.y()) < 1e-3) floor_hits += 1;
    }
    double floor_area = 0;
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        const Element& r = h.root(p);
        if (h.normal(r).y() > 0.99 && std::abs(r.centre.y()) < 1e-3) floor_area += r.area;
    }
    const double share = floor_area / top.area;
    EXPECT_TRUE(within_standard_errors("floor share", floor_hits / n, share,
                                       std::sqrt(share * (1 - share) / n)));
}

// The grouped descent through the clusters ends every ray where the one-ray descent from the
// top cluster ends it, with the same hierarchy and the same decisions counted.
TEST(Clusters, GroupedDescentEndsWhereOneRayDescentsEnd) {
    const PatchSet ps = build_patch_set(load_scene("cornell").mesh);
    std::size_t on_clusters = 0, on_patches = 0;
    for (const auto& [oracle_name, threshold_scale] : {std::pair<std::string, double>{"kl", 1},
                                                       {"kl", 1e4},
                                                       {"power", 1},
                                                       {"power", 1e4},
                                                       {"kl", 1e6}}) {
        // Named copies: clang before 16 does not let a lambda capture a structured binding.
        const std::string name = oracle_name;
        const double scale = threshold_scale;
        const Oracle& oracle = find_named(oracle_registry(), name);
        Hierarchy grouped(ps, {}), single(ps, {});
        for (Hierarchy* h : {&grouped, &single}) {
            for (std::size_t p = 0; p < h->patch_count(); ++p) {
                h->root(p).radiosity = h->root(p).unshot = Rgb(1.0, 0.5, 0.25);
            }
        }
        ClusterTree grouped_tree(grouped), single_tree(single);
        const EmbreeScene scene(ps.patches);
        auto context = [&](Hierarchy& h, ClusterTree& t) {
            return RefinementContext{
                .hierarchy = h,
                .oracle = oracle,
                .scene = scene,
                .threshold = scale * oracle.default_epsilon() * ps.max_emitted_power,
                .lines = 4,
                .seed = 11,
                .clusters = &t};
        };
        Rng rng(5, 1);
        std::vector<LinkQuery> queries(6'000);
        const auto patches = std::uint32_t(ps.patches.size());
        for (LinkQuery& q : queries) {
            q.receiver = SideRef(std::uint32_t(rng.uniform() * patches), kFront);
            q.source = SideRef(std::uint32_t(rng.uniform() * patches), kFront);
            q.y_uv = Vec2f(float(rng.uniform() * 0.5), float(rng.uniform() * 0.5));
            q.x_uv = Vec2f(float(rng.uniform() * 0.5), float(rng.uniform() * 0.5));
        }
        std::vector<Element*> receivers(queries.size(), nullptr);
        RefinementCounters grouped_counts, single_counts;
        {
            const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
            DescentScratch scratch;
            refine_links(context(grouped, grouped_tree), queries, receivers, grouped_counts,
                         scratch);
        }
        for (std::size_t k = 0; k < queries.size(); ++k) {
            const Element& e = refine_link(context(single, single_tree), queries[k], single_counts);
            ASSERT_EQ(receivers[k]->id, e.id) << name << " ray " << k;
            (is_cluster(e) ? on_clusters : on_patches) += 1;
        }
        EXPECT_EQ(grouped.element_count(), single.element_count()) << name;
        EXPECT_EQ(grouped_counts.oracle_calls, single_counts.oracle_calls) << name;
    }
    // A guard that the test reaches both kinds of element.
    EXPECT_GT(on_clusters, 0u);
    EXPECT_GT(on_patches, 0u);
}

SolverOptions clustered(std::uint64_t rays, std::uint64_t seed,
                        Clustering model = Clustering::isotropic) {
    SolverOptions o;
    o.clustering = model;
    o.rays = rays;
    o.seed = seed;
    o.lines = 4;
    o.refine_share = 1;  // the refined solve alone: the descent and deposits through clusters
    return o;
}

// A furnace of 6 x 16 x 16 patches: every patch's B is the exact K-bounce value
// E (1 - rho^(K+1)) / (1 - rho), t-tested over 10 seeds with Bonferroni over the patches. The
// furnace's irradiance is uniform, so isotropic deposits on clusters keep it exact; so do
// oriented ones, the box being convex (no side of a cluster hides another from a ray). A guard
// that clusters take deposits: the patches' spread about their mean is well below an
// unclustered solve's.
class ClusterModels : public testing::TestWithParam<Clustering> {};
INSTANTIATE_TEST_SUITE_P(Clusters, ClusterModels, cluster_models(), cluster_model_name);

TEST_P(ClusterModels, FurnaceOfManyPatchesIsExact) {
    const double rho = 0.5, e = 1;
    const auto mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 16, Rgb::Constant(rho), Rgb::Constant(e)));
    const std::size_t patches = mesh.n_faces();
    auto spread = [&](const Solution& sol) {
        double sum = 0, sum2 = 0;
        for (std::size_t p = 0; p < patches; ++p) {
            const double b = sol.hierarchy->root(p).radiosity[1];
            sum += b;
            sum2 += b * b;
        }
        return std::sqrt(sum2 / double(patches) - std::pow(sum / double(patches), 2));
    };
    // At this epsilon the later iterations' links are accepted at small clusters (at kl's
    // default every link goes down to the patches).
    const auto options = [](std::uint64_t seed) {
        SolverOptions o = clustered(30'000, seed, GetParam());
        o.epsilon = 3;
        return o;
    };
    double clustered_spread = 0;
    expect_furnace_per_patch(mesh, rho, e, 10, options, [&](const Solution& sol) {
        if (sol.options.seed == 1) clustered_spread = spread(sol);
    });
    SolverOptions none = options(1);
    none.clustering = Clustering::none;
    EXPECT_LT(clustered_spread, 0.8 * spread(solve(mesh, none)));
}

// Plates cut into 4 x 4 patches each, 1 m apart: the receiver plate's power is rho E F A, as
// the unclustered plates' (§8.5). The tree's first split parts the plates, so every cluster
// deposit on the receiver stays on it; the power oracle at this epsilon accepts the first
// iteration's link (receiver plate, top cluster), value 0.37 W, and refuses (top, top), 1 W
// (a guard: few distinct values).
TEST_P(ClusterModels, PlatesOfManyPatchesKeepTheFormFactor) {
    const double rho = 0.5;
    std::vector<TestPolygon> polygons;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Vec2 lo(i / 4.0, j / 4.0), hi((i + 1) / 4.0, (j + 1) / 4.0);
            TestPolygon emitter = axis_rectangle(2, 0, lo, hi, true);
            emitter.emission = Rgb::Constant(1);
            TestPolygon receiver = axis_rectangle(2, 1, lo, hi, false);
            receiver.reflectance = Rgb::Constant(rho);
            polygons.push_back(emitter);
            polygons.push_back(receiver);
        }
    }
    SolverOptions o = clustered(400'000, 21, GetParam());
    o.oracle = oracle("power");
    o.epsilon = 8;  // a threshold of 0.5 W: see the test's comment
    o.stop = 0.5;   // one iteration: the receiver's light alone, not what it reflects back
    const Solution sol = solve(make_patch_mesh(polygons), o);
    double power = 0;
    std::set<double> values;
    for (std::size_t p = 1; p < polygons.size(); p += 2) {
        const Element& r = sol.hierarchy->root(p);
        power += r.area * r.radiosity[1];
        values.insert(r.radiosity[1]);
    }
    const double f = parallel_rectangles(1, 1, 1), n0 = double(sol.stats.iterations[0].rays);
    EXPECT_TRUE(within_standard_errors("receiver power", power, rho * f,
                                       rho * std::sqrt(f * (1 - f) / n0)));
    EXPECT_LE(values.size(), 4u);
}

// Where the oracle refuses every cluster (kl's default epsilon on a furnace), a descent leaves
// the clusters at its receiver side's root and goes on from its source side's root, as without
// clusters: the same leaves and the same bits.
TEST(Clusters, WhereEveryClusterIsRefusedTheSolveIsTheUnclusteredOne) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 6, Rgb::Constant(0.5), Rgb::Constant(1)));
    SolverOptions o = clustered(40'000, 7);
    const Solution with = solve(mesh, o);
    o.clustering = Clustering::none;
    const Solution without = solve(mesh, o);
    EXPECT_GT(with.hierarchy->leaf_count(), mesh.n_faces());  // a guard: the patches refine
    expect_same_leaves(*with.hierarchy, *without.hierarchy);
    // Without a link cache each cluster's link to the top casts its lines once an iteration, not
    // once a ray.
    o.cache_mb = 0;
    o.threads = 1;  // two threads may both find a factor before either keeps it
    const std::uint64_t unclustered = solve(mesh, o).stats.lines_cast;
    o.clustering = Clustering::isotropic;
    const Solution clustered_solve = solve(mesh, o);
    Hierarchy h(build_patch_set(mesh), {});
    EXPECT_LE(clustered_solve.stats.lines_cast,
              unclustered + ClusterTree(h).size() * std::uint64_t(o.lines) *
                                clustered_solve.stats.iterations.size());
}

// The same seed gives the same hierarchy and values with one thread and with two.
TEST_P(ClusterModels, OneAndTwoThreadsGiveTheSameBits) {
    solve_on_one_and_two_threads(load_scene("cornell").mesh, clustered(100'000, 3, GetParam()));
}

}  // namespace
}  // namespace hmcr::test
