// SPDX-License-Identifier: Apache-2.0
// Monte Carlo form factors against the exact values of docs/design.md §8.
//
// Line pairs (x uniform on i, y uniform on j, the docs/design.md §4 kernel with Embree
// visibility) estimate F_ij = A_j E[F(x, y)]; the standard error is the sample one. For
// elements sharing an edge that estimator has infinite variance (F ~ 1/r^2 near the edge, a
// tail P(F > t) ~ t^-3/2), so its sample standard error is no valid tolerance; the
// perpendicular cases use local lines instead (cosine rays from x: the hit fraction is a
// Bernoulli mean with exact variance p(1-p)/N).
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/hierarchy.h"
#include "radiosity/line_sampler.h"
#include "rays/element_sampler.h"
#include "rays/embree_scene.h"
#include "rays/point_kernel.h"
#include "rays/sampling.h"
#include "tests/support/analytic.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

struct TwoPatches {
    Hierarchy hierarchy;
    EmbreeScene scene;
    explicit TwoPatches(const std::vector<TestPolygon>& polys)
        : hierarchy(build_patch_set(make_patch_mesh(polys)), {}),
          scene(hierarchy.patch_set().patches) {}
};

TestPolygon rect(int axis, double value, Vec2 lo, Vec2 hi, bool positive) {
    TestPolygon p = axis_rectangle(axis, value, lo, hi, positive);
    p.reflectance = Rgb::Constant(0.5);
    return p;
}

// F_ij from line pairs between the two root elements.
Estimate line_pair_form_factor(const TwoPatches& s, std::size_t n, std::uint64_t seed) {
    std::vector<double> kernel(n);
    Rng rng(seed, 0);
    sample_kernel(s.scene, s.hierarchy, s.hierarchy.root(0), s.hierarchy.root(1), rng, kernel);
    Estimate e = estimate_mean(kernel);
    const double area_j = s.hierarchy.root(1).area;
    return {e.mean * area_j, e.standard_error * area_j, n};
}

// F_ij from local lines: cosine rays from uniform points of i, the fraction that hits j.
Estimate local_line_form_factor(const TwoPatches& s, int i, int j, std::size_t n,
                                std::uint64_t seed) {
    const Patch& p = s.hierarchy.patch_set().patches[i];
    Rng rng(seed, 1);
    std::size_t hits = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3 x = p.point(sample_element(p, Domain::root(), rng.uniform(), rng.uniform()));
        const Vec3 d = sample_cosine_hemisphere(p.normal, rng.uniform(), rng.uniform());
        const auto hit = s.scene.first_hit(x, d);
        hits += hit && hit->patch == std::uint32_t(j);
    }
    const double f = double(hits) / double(n);
    return {f, std::sqrt(f * (1 - f) / double(n)), n};
}

TEST(AnalyticFormFactors, ReproduceTheSpecValues) {
    EXPECT_NEAR(parallel_rectangles(1, 1, 1), 0.19982, 5e-6);
    EXPECT_NEAR(parallel_rectangles(1, 1, 0.5), 0.41525, 5e-6);
    EXPECT_NEAR(parallel_rectangles(2, 1, 1), 0.28588, 5e-6);
    EXPECT_NEAR(perpendicular_rectangles(1, 1, 1), 0.20004, 5e-6);
    EXPECT_NEAR(perpendicular_rectangles(1, 2, 1), 0.11643, 5e-6);
    EXPECT_NEAR(perpendicular_rectangles(1, 1, 2), 0.23285, 5e-6);
    EXPECT_NEAR(point_to_centred_rectangle(1, 1, 1), 0.23946, 5e-6);
}

struct ParallelCase {
    double a, b, c;
};
class ParallelPlates : public testing::TestWithParam<ParallelCase> {};

TEST_P(ParallelPlates, LinePairsMatchTheExactFormFactor) {
    const auto [a, b, c] = GetParam();
    const TwoPatches s({rect(2, 0, {0, 0}, {a, b}, true), rect(2, c, {0, 0}, {a, b}, false)});
    const Estimate f = line_pair_form_factor(s, 1'000'000, 11);
    EXPECT_TRUE(within_standard_errors("F parallel", f.mean, parallel_rectangles(a, b, c),
                                       f.standard_error));
}

INSTANTIATE_TEST_SUITE_P(Spec, ParallelPlates,
                         testing::Values(ParallelCase{1, 1, 1}, ParallelCase{1, 1, 0.5},
                                         ParallelCase{2, 1, 1}));

struct PerpendicularCase {
    double l, w, h;
};
class PerpendicularPlates : public testing::TestWithParam<PerpendicularCase> {};

// i: the w x l rectangle in the plane z = 0 (x in [0, w], y in [0, l]) facing +z; j: the h x l
// rectangle in the plane x = 0 facing +x; they share the edge x = z = 0.
TwoPatches perpendicular(double l, double w, double h) {
    return TwoPatches({rect(2, 0, {0, 0}, {w, l}, true), rect(0, 0, {0, 0}, {l, h}, true)});
}

TEST_P(PerpendicularPlates, LocalLinesMatchTheExactFormFactor) {
    const auto [l, w, h] = GetParam();
    const Estimate f = local_line_form_factor(perpendicular(l, w, h), 0, 1, 1'000'000, 12);
    EXPECT_TRUE(within_standard_errors("F perpendicular", f.mean, perpendicular_rectangles(l, w, h),
                                       f.standard_error));
}

INSTANTIATE_TEST_SUITE_P(Spec, PerpendicularPlates,
                         testing::Values(PerpendicularCase{1, 1, 1}, PerpendicularCase{1, 2, 1},
                                         PerpendicularCase{1, 1, 2}));

TEST(Reciprocity, AreaTimesFormFactorIsSymmetric) {
    const TwoPatches s = perpendicular(1, 2, 1);  // A_0 = 2, A_1 = 1
    const Estimate f01 = local_line_form_factor(s, 0, 1, 1'000'000, 13);
    const Estimate f10 = local_line_form_factor(s, 1, 0, 1'000'000, 14);
    const double se = std::hypot(2 * f01.standard_error, f10.standard_error);
    EXPECT_TRUE(within_standard_errors("A0 F01 - A1 F10", 2 * f01.mean - f10.mean, 0, se));
}

TEST(PointToRectangle, KernelIntegralMatchesTheDifferentialFormFactor) {
    // A point 1 m below the centre of a unit square, both facing each other.
    const TwoPatches s(
        {rect(2, 0, {-0.5, -0.5}, {0.5, 0.5}, false), rect(2, -5, {-0.5, -0.5}, {0.5, 0.5}, true)});
    const Patch& square = s.hierarchy.patch_set().patches[0];
    const Vec3 x(0, 0, -1), nx(0, 0, 1);
    Rng rng(15, 0);
    std::vector<double> f(1'000'000);
    for (double& v : f) {
        const Vec3 y =
            square.point(sample_element(square, Domain::root(), rng.uniform(), rng.uniform()));
        v = square.area * point_kernel(x, nx, y, square.normal) * s.scene.visible(x, y);
    }
    const Estimate e = estimate_mean(f);
    EXPECT_TRUE(within_standard_errors("F point-rectangle", e.mean,
                                       point_to_centred_rectangle(1, 1, 1), e.standard_error));
}

TEST(Visibility, AnOccluderBetweenThePlatesBlocksEveryLine) {
    const TwoPatches s({rect(2, 0, {0, 0}, {1, 1}, true), rect(2, 1, {0, 0}, {1, 1}, false),
                        rect(2, 0.5, {-1, -1}, {2, 2}, true)});
    EXPECT_EQ(line_pair_form_factor(s, 10'000, 16).mean, 0.0);
}

}  // namespace
}  // namespace hmcr::test
