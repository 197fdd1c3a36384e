// SPDX-License-Identifier: Apache-2.0
// The bias of stopping (radiosity/truncation.h) on the furnace, where it is known exactly.
#include "radiosity/truncation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/oracle_registry.h"
#include "radiosity/solver.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// A closed box of rho = 0.5, E = 1: converged, every patch has B = E / (1 - rho), so the
// reflected power is A E rho / (1 - rho). In a furnace every ray's power lands (but for the few
// lost at the edges), so the decay of each iteration is rho and the reported tail is the true one.
TEST(Truncation, TheFurnaceTailIsTheMissingReflectedPower) {
    const double rho = 0.5, e = 1;
    const auto mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(rho), Rgb::Constant(e)));
    for (const double stop : {1e-2, 1e-4}) {
        SolverOptions o;
        o.oracle = oracle_registry().find("power");
        o.rays = 1'000'000;
        o.stop = stop;
        const Solution sol = solve(mesh, o);
        const TruncationBias t = truncation_bias(sol);
        ASSERT_LT(sol.stats.unshot_power.sum(), stop * sol.stats.emitted_power.sum())
            << "the rays ran out before the stop rule";
        const double area = 6, converged = area * e * rho / (1 - rho);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(t.decay[c], rho, 1e-12);
            // Rays that slip through the box's edges or reach a back face (a few in a million)
            // take their power and its later bounces, at most lost / (1 - rho), with them.
            const double lost = sol.stats.escaped_power[c] + sol.stats.back_face_power[c];
            EXPECT_NEAR(t.reflected[c] + t.missing[c], converged,
                        1e-9 * converged + lost / (1 - rho));
            EXPECT_LT(lost, 1e-4 * area * e);
            EXPECT_GT(t.relative[c], 0);
            // U < stop x emitted, and the tail of a decay of 0.5 is U itself.
            EXPECT_LT(t.relative[c], stop * area * e / t.reflected[c]);
        }
    }
}

}  // namespace
}  // namespace hmcr::test
