// SPDX-License-Identifier: Apache-2.0
// The link cache (docs/design.md §4.3) and the mi/kl identity at the level of whole solves.
#include "radiosity/link_cache.h"

#include <gtest/gtest.h>

#include "meshes/scene.h"
#include "radiosity/oracle_registry.h"
#include "radiosity/solver.h"

namespace hmcr::test {
namespace {

using Leaves = std::vector<std::pair<ElementId, Rgb>>;

Leaves leaves_of(const Solution& sol) {
    Leaves out;
    sol.hierarchy->for_each_leaf([&](const Element& e) { out.emplace_back(e.id, e.radiosity); });
    return out;
}

void expect_same(const Leaves& a, const Leaves& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        ASSERT_EQ(a[k].first, b[k].first) << k;
        ASSERT_TRUE((a[k].second == b[k].second).all()) << a[k].first.to_string();
    }
}

SolverOptions kl_options() {
    SolverOptions o;
    o.oracle = oracle_registry().find("kl");
    o.rays = 300'000;
    o.seed = 17;
    o.lines = 10;
    return o;
}

TEST(LinkCache, StoresFindsAndEvictsWithinItsBudget) {
    LinkCache cache(64 * 4);  // 4 sets of 2 pairs
    EXPECT_EQ(cache.capacity(), 8u);
    EXPECT_EQ(cache.bytes(), 256u);
    std::vector<Element> elements(40);
    EXPECT_FALSE(cache.find(&elements[0], &elements[1]));
    cache.insert(&elements[0], &elements[1], 0.5);
    EXPECT_EQ(cache.find(&elements[0], &elements[1]).value_or(-1), 0.5);
    EXPECT_FALSE(cache.find(&elements[1], &elements[0]));  // pairs are ordered
    for (std::size_t k = 2; k < elements.size(); ++k) cache.insert(&elements[k], &elements[0], k);
    EXPECT_GT(cache.evictions(), 0u);  // 39 pairs in 8 places
}

// Whatever the cache size (none, a few KiB that evict all the time, the default), the same
// seed gives the same hierarchy and values: a pair's lines come from the pair's own stream.
TEST(LinkCache, EvictionAndSizeDoNotChangeTheSolution) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = kl_options();
    const Solution big = solve(scene.mesh, o);
    o.cache_mb = 0.01;
    const Solution tiny = solve(scene.mesh, o);
    o.cache_mb = 0;
    const Solution none = solve(scene.mesh, o);
    EXPECT_GT(tiny.stats.cache_evictions, 0u);
    EXPECT_EQ(none.stats.cache_hits, 0u);
    // The same links are decided whatever the cache holds; it only answers some of them.
    EXPECT_GT(big.stats.cache_hits, 0u);
    EXPECT_EQ(big.stats.cache_hits + big.stats.oracle_evaluations, none.stats.oracle_evaluations);
    EXPECT_EQ(tiny.stats.cache_hits + tiny.stats.oracle_evaluations, none.stats.oracle_evaluations);
    expect_same(leaves_of(big), leaves_of(tiny));
    expect_same(leaves_of(big), leaves_of(none));
}

// docs/design.md §4.2: mi = kl / (A_T N_s) on the same lines, so mi at eps_kl / (A_T N_s) refines
// exactly like kl at eps_kl.
TEST(LinkCache, MiAtTheScaledEpsilonBuildsTheSameHierarchyAsKl) {
    const Scene scene = load_scene("cornell");
    SolverOptions o = kl_options();
    o.epsilon = 1e-5;
    const Solution kl = solve(scene.mesh, o);
    o.oracle = oracle_registry().find("mi");
    o.epsilon = 1e-5 / (kl.hierarchy->patch_set().total_area * o.lines);
    const Solution mi = solve(scene.mesh, o);
    EXPECT_GT(kl.stats.leaves, 1000u);
    expect_same(leaves_of(kl), leaves_of(mi));
}

}  // namespace
}  // namespace hmcr::test
