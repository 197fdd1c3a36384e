// SPDX-License-Identifier: Apache-2.0
// Clusters over two-sided patches (docs/design.md §2.7): a cluster's deposit never reaches a side
// that faces away from where the light is, so the two-sided furnace stays exact.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "radiosity/solver.h"
#include "tests/support/cluster_models.h"
#include "tests/support/furnace.h"
#include "tests/support/same_leaves.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// A closed box of 6 x 12 x 12 two-sided patches. Inner sides (the fronts) emit E = 1 and
// reflect rho = 0.5; outer sides (the backs) emit E_out = 0.3 and reflect 0.5 too. Every ray
// from an outer side leaves into the void (the box is convex) and no ray from inside reaches an
// outer side, so an outer side's B is exactly E_out, bit for bit. Inside, the walls are the
// one-sided furnace: after K iterations B = E (1 - rho^(K+1)) / (1 - rho) on every patch, in
// expectation, t-tested over 8 seeds with Bonferroni over the patches. A guard that clusters
// take deposits: the inner sides' spread about their mean is well below an unclustered solve's.
// The walls of a closed unit box, n x n patches a face, each two-sided: fronts inside.
PatchMesh two_sided_box(int n, double rho, double e, double e_out) {
    std::vector<TestPolygon> walls =
        inward_box({0, 0, 0}, {1, 1, 1}, n, Rgb::Constant(rho), Rgb::Constant(e));
    for (TestPolygon& w : walls) {
        w.two_sided = true;
        w.back_reflectance = Rgb::Constant(rho);
        w.back_emission = Rgb::Constant(e_out);
    }
    return make_patch_mesh(walls);
}

// At this epsilon clusters take deposits (kl's default refuses them all).
SolverOptions clustered(std::uint64_t seed, Clustering model) {
    SolverOptions o;
    o.clustering = model;
    o.rays = 30'000;
    o.seed = seed;
    o.lines = 4;
    o.refine_share = 1;  // the frozen pass ignores clusters
    o.epsilon = 3;
    return o;
}

// Isotropic and oriented clusters alike.
class TwoSidedClusterModels : public testing::TestWithParam<Clustering> {};
INSTANTIATE_TEST_SUITE_P(ClustersTwoSided, TwoSidedClusterModels, cluster_models(),
                         cluster_model_name);

TEST_P(TwoSidedClusterModels, FurnaceOfTwoSidedWallsIsExactInsideAndOutside) {
    const double rho = 0.5, e = 1, e_out = 0.3;
    const PatchMesh mesh = two_sided_box(12, rho, e, e_out);
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
    std::vector<std::vector<double>> inside(patches);
    std::size_t iterations = 0;
    double clustered_spread = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const Solution sol = solve(mesh, clustered(seed, GetParam()));
        if (seed > 1) {
            ASSERT_EQ(sol.stats.value_iterations().size(), iterations) << "seed " << seed;
        }
        iterations = sol.stats.value_iterations().size();
        for (std::size_t p = 0; p < patches; ++p) {
            inside[p].push_back(sol.hierarchy->root(p).radiosity[1]);
            const Element* out = sol.hierarchy->back_root(p);
            ASSERT_NE(out, nullptr);
            ASSERT_EQ(out->radiosity[1], e_out) << "outer side of patch " << p << ", seed " << seed;
        }
        if (seed == 1) clustered_spread = spread(sol);
    }
    const double expected = furnace_value(rho, e, iterations);
    for (std::size_t p = 0; p < patches; ++p) {
        EXPECT_TRUE(t_test("inner side of patch " + std::to_string(p), inside[p], expected, 0,
                           int(patches)));
    }
    SolverOptions none = clustered(1, GetParam());
    none.clustering = Clustering::none;
    EXPECT_LT(clustered_spread, 0.8 * spread(solve(mesh, none)));
}

// The same seed gives the same hierarchy and values with one thread and with two, through the
// top cluster joining fronts and backs.
TEST_P(TwoSidedClusterModels, OneAndTwoThreadsGiveTheSameBits) {
    solve_on_one_and_two_threads(two_sided_box(6, 0.5, 1, 0.3), clustered(5, GetParam()));
}

}  // namespace
}  // namespace hmcr::test
