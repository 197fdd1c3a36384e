// SPDX-License-Identifier: Apache-2.0
// Inside a sphere F(x, y) = 1 / A_T for all x, y (docs/design.md §8), so one emitter of power Phi
// and a uniform rho give every other patch B = rho Phi / (A_T (1 - rho)); after K shooting
// iterations the geometric series stops at rho^K: B_K = rho Phi (1 - rho^K) / (A_T (1 - rho)).
//
// The sphere is tessellated (an icosphere of 5120 triangles), so the kernel differs from
// 1 / A_T. Bound used: at a facet point the two cosines of the kernel differ from those of the
// sphere by at most the angle alpha between the facet normal and the sphere normal at its
// corners, and the distance by the facet's sagitta s; the relative bias of a region's
// irradiance is then at most 2 (1 - cos alpha) + 4 s / R (first order, both factors).
// Regions (the 8 octants) average over many facets, so the Monte Carlo error is small.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/oracle_registry.h"
#include "radiosity/solver.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

TEST(Sphere, EveryRegionGetsTheUniformRadiosity) {
    const double rho = 0.5, radius = 1;
    auto faces = inward_icosphere(4, radius, Rgb::Constant(rho));
    faces[0].emission = Rgb::Constant(100);
    double alpha = 0, sagitta = 0;
    for (const auto& f : faces) {
        const Vec3 n =
            (f.corners[1] - f.corners[0]).cross(f.corners[2] - f.corners[0]).normalized();
        const Vec3 c = (f.corners[0] + f.corners[1] + f.corners[2]) / 3;
        ASSERT_LT(n.dot(c), 0) << "faces must point inward";
        for (const Vec3& v : f.corners) alpha = std::max(alpha, std::acos(-n.dot(v.normalized())));
        sagitta = std::max(sagitta, radius - c.norm());
    }
    const double bias = 2 * (1 - std::cos(alpha)) + 4 * sagitta / radius;
    const auto mesh = make_patch_mesh(faces);

    std::vector<std::vector<double>> octant(8);
    std::size_t iterations = 0;
    double total_area = 0, phi = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        SolverOptions o;
        o.rays = 1'000'000;
        o.seed = seed;
        const Solution sol = solve(mesh, o);
        const Hierarchy& h = *sol.hierarchy;
        // The expected value below assumes one K for every seed.
        if (seed > 1) {
            ASSERT_EQ(sol.stats.value_iterations().size(), iterations) << "seed " << seed;
        }
        iterations = sol.stats.value_iterations().size();
        total_area = h.patch_set().total_area;
        phi = h.patch_set().emitted_power[0];
        std::array<double, 8> area{}, power{};
        for (std::size_t p = 1; p < h.patch_count(); ++p) {
            const Vec3 c = h.root(p).centre;
            const int k = (c.x() > 0) + 2 * (c.y() > 0) + 4 * (c.z() > 0);
            area[k] += h.root(p).area;
            power[k] += h.root(p).area * h.root(p).radiosity[0];
        }
        for (int k = 0; k < 8; ++k) octant[k].push_back(power[k] / area[k]);
    }
    const double expected =
        rho * phi * (1 - std::pow(rho, double(iterations))) / (total_area * (1 - rho));
    for (int k = 0; k < 8; ++k) {  // Bonferroni over the 8 octants
        EXPECT_TRUE(t_test("octant " + std::to_string(k), octant[k], expected, bias * expected, 8));
    }
}

}  // namespace
}  // namespace hmcr::test
