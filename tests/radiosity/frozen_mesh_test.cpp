// SPDX-License-Identifier: Apache-2.0
// Solving on a frozen mesh (a study's mesh error): the same leaves, no oracle, and an error that
// falls as 1/sqrt(rays) to the error of the mesh itself.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radiosity/oracle_registry.h"
#include "radiosity/solver.h"
#include "tests/support/analytic.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// The plates of solver_test: a unit emitter (rho = 0, E = 1) 1 m below a unit receiver
// (rho = 0.5), whose exact radiosity at (x, y) is rho E F(point -> emitter).
constexpr double kRho = 0.5;

PatchMesh plates() { return unit_plates(kRho); }

double exact_b(double x, double y) {
    return kRho * point_to_parallel_rectangle(-x, 1 - x, -y, 1 - y, 1);
}

// A refined mesh of the plates (power oracle, small epsilon): its hierarchy is the shape.
Solution refined_plates() {
    SolverOptions o;
    o.oracle = oracle_registry().find("power");
    o.epsilon = 2e-3;
    o.rays = 20'000;
    return solve(plates(), o);
}

std::vector<ElementId> leaf_ids(const Hierarchy& h) {
    std::vector<ElementId> ids;
    h.for_each_leaf([&](const Element& e) { ids.push_back(e.id); });
    return ids;
}

TEST(FrozenMesh, KeepsTheLeavesAndAsksNoOracle) {
    const Solution shape = refined_plates();
    ASSERT_GT(shape.stats.leaves, 20u);
    SolverOptions o = shape.options;
    o.rays = 50'000;
    o.seed = 9;
    const Solution frozen = solve_on_mesh(plates(), o, shape);
    EXPECT_EQ(leaf_ids(*frozen.hierarchy), leaf_ids(*shape.hierarchy));
    EXPECT_EQ(frozen.stats.oracle_calls, 0u);
    EXPECT_EQ(frozen.stats.leaves, shape.stats.leaves);
}

// Per receiver leaf: its area weight, its exact mean radiosity, and the binomial variance of
// its estimate after N0 first-iteration rays (hits ~ Binomial(N0, p), p = A_e F_e / A_emitter).
struct Leaf {
    double weight, mean, variance_n0;  // variance_n0 = Var(B_e) * N0
    std::vector<double> exact;         // exact B at the quadrature points
};

// 8 x 8 midpoint quadrature of each leaf (an axis-aligned rectangle of the receiver).
std::vector<Leaf> receiver_leaves(const Hierarchy& h) {
    std::vector<Leaf> out;
    Hierarchy::visit_leaves(h.root(1), [&](const Element& e) {
        const auto c = h.corners(e);
        double x0 = c[0].x(), x1 = x0, y0 = c[0].y(), y1 = y0;
        for (const Vec3& p : c) {
            x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
            y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
        }
        Leaf leaf{e.area, 0, 0, {}};
        constexpr int n = 8;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double b =
                    exact_b(x0 + (i + 0.5) * (x1 - x0) / n, y0 + (j + 0.5) * (y1 - y0) / n);
                leaf.exact.push_back(b);
                leaf.mean += b / (n * n);
            }
        const double p = e.area * leaf.mean / kRho;  // emitter area and E are 1
        leaf.variance_n0 = std::pow(kRho / e.area, 2) * p * (1 - p);
        out.push_back(leaf);
    });
    return out;
}

// err^2 = sum_e w_e mean_q (B_e - B(q))^2 splits exactly into the mesh's own error, sum_e w_e
// mean_q (mean_e - B(q))^2, plus the noise sum_e w_e (B_e - mean_e)^2 (the cross term is zero
// as mean_e is the quadrature mean). The noise's expectation is sum_e w_e Var(B_e), which is
// 1/N0 times a constant: the frozen re-solve's error falls as 1/sqrt(rays) to the mesh error.
TEST(FrozenMesh, ErrorFallsAsOneOverRootRaysToTheMeshError) {
    const Solution shape = refined_plates();
    const std::vector<Leaf> leaves = receiver_leaves(*shape.hierarchy);
    double mesh_error2 = 0;
    for (const Leaf& l : leaves)
        for (double b : l.exact)
            mesh_error2 += l.weight * (l.mean - b) * (l.mean - b) / double(l.exact.size());
    EXPECT_GT(mesh_error2, 0);

    std::vector<double> errors, expected_noise;
    for (const std::uint64_t rays : {40'000ull, 640'000ull, 10'240'000ull}) {
        SolverOptions o = shape.options;
        o.rays = rays;
        o.seed = 5;
        const Solution frozen = solve_on_mesh(plates(), o, shape);
        const double n0 = double(frozen.stats.iterations.at(0).rays);
        std::vector<double> b;
        Hierarchy::visit_leaves(frozen.hierarchy->root(1),
                                [&](const Element& e) { b.push_back(e.radiosity[1]); });
        ASSERT_EQ(b.size(), leaves.size());
        double noise = 0, expected = 0, variance = 0, error2 = 0;
        for (std::size_t k = 0; k < leaves.size(); ++k) {
            const Leaf& l = leaves[k];
            noise += l.weight * (b[k] - l.mean) * (b[k] - l.mean);
            expected += l.weight * l.variance_n0 / n0;
            variance += 2 * std::pow(l.weight * l.variance_n0 / n0, 2);  // (chi^2, 1 dof each)
            for (double x : l.exact)
                error2 += l.weight * (b[k] - x) * (b[k] - x) / double(l.exact.size());
        }
        EXPECT_NEAR(error2, mesh_error2 + noise, 1e-12 * error2);
        EXPECT_TRUE(within_standard_errors("noise at " + std::to_string(rays) + " rays", noise,
                                           expected, std::sqrt(variance)));
        errors.push_back(std::sqrt(error2));
        expected_noise.push_back(expected);
    }
    // The noise is tested against its expectation above, so the error falls as 1/sqrt(rays)
    // towards the mesh's own; at 10 M rays the expected noise is under 1% of the mesh's squared
    // error, so there the error is the mesh's to half a percent.
    EXPECT_LT(errors[1], errors[0]);
    EXPECT_LT(errors[2], errors[1]);
    EXPECT_LT(expected_noise[2], 0.01 * mesh_error2);
}

}  // namespace
}  // namespace hmcr::test
