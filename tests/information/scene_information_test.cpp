// SPDX-License-Identifier: Apache-2.0
// Scene information measures (docs/design.md §7) against exact values and known properties, with
// local lines (global lines: global_lines_test.cpp).
//
// Tolerances: z = 4 batch-means standard errors, plus, where the plug-in entropy's bias
// matters, Paninski's bound (tests/support/information.h).
#include "information/scene_information.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "information/form_factors.h"
#include "tests/support/analytic.h"
#include "tests/support/information.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

PatchSet cube(double size, int n) { return cube_patches(size, n); }

PatchSet sphere(int level) {
    return build_patch_set(make_patch_mesh(inward_icosphere(level, 1.0, Rgb::Constant(0.5))));
}

LineOptions lines(std::uint64_t n, std::uint64_t seed = 7) {
    return {LineMethod::local, n, 16, seed};
}
// The longest edge of any patch.
double longest_edge(const PatchSet& set) {
    double h = 0;
    for (const Patch& p : set.patches) {
        for (int k = 0; k < p.corner_count; ++k) {
            h = std::max(h, (p.corner[(k + 1) % p.corner_count] - p.corner[k]).norm());
        }
    }
    return h;
}

TEST(SceneInformation, CubeFormFactorsMatchExactValues) {
    const PatchSet set = cube(1, 1);
    const EmbreeScene scene(set.patches);
    const SparseFormFactors f = form_factors(trace_local_lines(set, scene, lines(320'000)));
    const auto [opposite, adjacent, h_p, h_s, i_s] = empty_cube();
    for (std::size_t j = 1; j < 6; ++j) {
        const bool facing = set.patches[0].normal.dot(set.patches[j].normal) < -0.5;
        const double exact = facing ? opposite : adjacent;
        const double se = std::sqrt(exact * (1 - exact) / double(f.rays[0]));
        EXPECT_TRUE(within_standard_errors("F_0" + std::to_string(j), f(0, j), exact, se));
    }
    EXPECT_EQ(f(0, 0), 0.0);
    EXPECT_LE(f.rows[0].size(), 5u);
}

TEST(SceneInformation, EmptyCubeMatchesExactMeasures) {
    const auto [opposite, adjacent, h_p, h_s, i_s] = empty_cube();
    EXPECT_NEAR(opposite, 0.19982, 5e-6);
    EXPECT_NEAR(adjacent, 0.20004, 5e-6);
    EXPECT_NEAR(opposite + 4 * adjacent, 1.0, 1e-9);  // row sum of a closed scene

    const PatchSet set = cube(1, 1);
    const LineOptions options = lines(1'600'000);
    const auto [m, bias, open] = measure_channel(set, options);
    // 266,672 rays per face: the bias bound is 2.7e-5 bits, about 2 standard errors.
    EXPECT_NEAR(m.h_p.estimate, h_p, 1e-12);
    EXPECT_TRUE(within_standard_errors("H_S", m.h_s.estimate, h_s, m.h_s.standard_error, bias));
    EXPECT_TRUE(within_standard_errors("I_S", m.i_s.estimate, i_s, m.i_s.standard_error, bias));
    EXPECT_TRUE(
        within_standard_errors("H_J", m.h_j.estimate, h_p + h_s, m.h_j.standard_error, bias));
    EXPECT_GT(m.i_s.standard_error, 0.0);
    EXPECT_EQ(m.lines, 1'600'032u);
    EXPECT_LT(m.samples_open, m.samples / 10'000);
}

TEST(SceneInformation, ScalingChangesNoMeasure) {
    const InformationMeasures a = scene_information(cube(1, 1), lines(200'000));
    const InformationMeasures b = scene_information(cube(3, 1), lines(200'000));
    // Same seed, scale-equivariant sampling: the same lines hit the same patches.
    EXPECT_NEAR(a.i_s.estimate, b.i_s.estimate, 1e-9);
    EXPECT_NEAR(a.i_cs.estimate, b.i_cs.estimate, 1e-9);
    EXPECT_EQ(a.samples_open, b.samples_open);
    // Independent seeds agree within their combined standard errors.
    const InformationMeasures c = scene_information(cube(3, 1), lines(200'000, 8));
    const auto combined = [](const auto& x, const auto& y) {
        return std::hypot(x.standard_error, y.standard_error);
    };
    EXPECT_TRUE(
        within_standard_errors("I_S", c.i_s.estimate, a.i_s.estimate, combined(a.i_s, c.i_s)));
    EXPECT_TRUE(within_standard_errors("I^c_S", c.i_cs.estimate, a.i_cs.estimate,
                                       combined(a.i_cs, c.i_cs)));
}

TEST(SceneInformation, ResultsDoNotDependOnThreadCount) {
    const PatchSet set = cube(1, 2);
    const EmbreeScene scene(set.patches);
    const ChannelSamples many = trace_local_lines(set, scene, lines(100'000));
    const ChannelSamples one = [&] {
        const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        return trace_local_lines(set, scene, lines(100'000));
    }();
    EXPECT_EQ(many.target, one.target);
    EXPECT_EQ(many.log_kernel_sum, one.log_kernel_sum);
    EXPECT_EQ(many.log_kernel_count, one.log_kernel_count);
}

// The interior of a sphere has A_T F(x, y) = 1 (cos = r / 2R at both ends), so I^c_S = 0. An
// inscribed tessellation's I^c_S is the KL divergence of its pair density A_T F from uniform
// pairs, so it is >= 0. How fast it falls: a flat face's normal leans from the sphere's by up to
// its angular radius, O(h / R), which changes cos by O(h / R) sin while cos itself is r / 2R,
// so A_T F = 1 + delta with delta = O((h / R)(R / r)). KL ~ E[delta^2] / (2 ln 2), and E over
// uniform pairs of (R / r)^2 cut off at r ~ h grows like ln(R / h):
//   I^c_S = (h / R)^2 (a + b ln(R / h)) + o((h / R)^2).
// Shrinking h to h' multiplies I^c_S by q = (h'/h)^2 (1 + b ln(h/h') / (a + b ln(R/h))), which
// tends to 1/4 for halvings; with a, b >= 0 it is at most (h'/h)^2 (1 + ln(h/h') / ln(R/h)),
// below 1/2 for the levels' edge ratios (0.51-0.53) once h < R/3. Measured (4 M lines, levels
// 1..5): I^c_S / (h/R)^2 = 0.433, 0.462, 0.526, 0.588, 0.644 (one step of b ln 2 = 0.06 a level,
// so b = 0.09, a = 0.39), and q = 0.29, 0.29, 0.28, 0.27. The test: I^c_S >= 0, and each level
// from h < R/3 on at least halves it, a geometric approach to 0.
TEST(SceneInformation, TessellatedSphereContinuousInformationFallsGeometrically) {
    std::vector<InformationMeasures> m;
    for (int level = 2; level <= 4; ++level) {
        const PatchSet set = sphere(level);
        ASSERT_LT(longest_edge(set), 1.0 / 3.0) << level;  // the premise of the bound on q
        m.push_back(scene_information(set, lines(1'000'000)));
        EXPECT_GT(m.back().i_cs.estimate + kZ * m.back().i_cs.standard_error, 0.0) << level;
    }
    for (std::size_t k = 0; k + 1 < m.size(); ++k) {
        const auto& coarse = m[k].i_cs;
        const auto& fine = m[k + 1].i_cs;
        EXPECT_LT(fine.estimate + kZ * fine.standard_error,
                  0.5 * (coarse.estimate - kZ * coarse.standard_error))
            << "levels " << k + 2 << " and " << k + 3;
    }
}

// H_S tends to H_P: H_P - H_S = I_S <= I^c_S (discretising loses information), which tends to 0
// (above), with the plug-in bias of I_S added.
TEST(SceneInformation, TessellatedSphereVisibilityEntropyNearPositional) {
    for (int level = 1; level <= 2; ++level) {
        const auto [m, bias, open] = measure_channel(sphere(level), lines(2'000'000));
        const double se = m.h_s.standard_error + m.i_cs.standard_error;
        EXPECT_LE(m.h_p.estimate - m.h_s.estimate, m.i_cs.estimate + bias + kZ * se) << level;
    }
}

TEST(SceneInformation, RefiningDoesNotLowerMutualInformation) {
    const PatchSet coarse = cube(1, 1), fine = cube(1, 2);
    const LineOptions options = lines(1'600'000);
    const InformationMeasures c = scene_information(coarse, options);
    const auto [f, bias, open] = measure_channel(fine, options);
    // The plug-in bias raises I_S, more so for more patches: subtract it from the finer one.
    EXPECT_GT(f.i_s.estimate - bias - kZ * (f.i_s.standard_error + c.i_s.standard_error),
              c.i_s.estimate);
    // I_S < I^c_S, the discretisation error beyond its errors and the bias of I_S.
    for (const auto* m : {&c, &f}) {
        EXPECT_GT(m->discretisation_error.estimate - kZ * m->discretisation_error.standard_error,
                  bias);
    }
    // I^c_S is a property of the scene, not of its discretisation.
    EXPECT_TRUE(within_standard_errors("I^c_S", f.i_cs.estimate, c.i_cs.estimate,
                                       f.i_cs.standard_error + c.i_cs.standard_error));
}

// The reported bias extrapolates the batches (B times fewer lines) to all lines as 1/n. For the
// empty cube that is Miller-Madow's first-order plug-in bias of H_S, -(K - 1) / (2 n ln 2)
// with K = 5 faces in view and n rays a face; Harris's second-order term (1 - sum 1/F) /
// (12 n^2 ln 2) adds (B + 1) times its value at n, 8e-7 bits here. A t test over 8 seeds.
TEST(SceneInformation, BiasEstimateIsTheMillerMadowBias) {
    const PatchSet set = cube(1, 1);
    const LineOptions options = lines(48'000);
    const double n = double(local_line_counts(set, options)[0]);
    const double first_order = -4 / (2 * n * std::log(2.0));
    const double second_order = 17 * 24 / (12 * n * n * std::log(2.0));
    std::vector<double> h_s, i_cs;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const InformationMeasures m = scene_information(set, lines(48'000, seed));
        h_s.push_back(m.h_s.bias);
        // The rest of I_S is linear in F, which the batches average exactly (equal batches).
        EXPECT_NEAR(m.i_s.bias, -m.h_s.bias, 1e-12);
        // I^c_S is a mean: with no open rays every batch has the same count, so the batches'
        // mean is the pooled mean and the reported bias is 0 up to rounding.
        ASSERT_EQ(m.samples_open, 0u);
        EXPECT_LT(std::abs(m.i_cs.bias), 1e-12);
    }
    EXPECT_TRUE(t_test("H_S bias", h_s, first_order, second_order));
}

TEST(SceneInformation, JsonHasEveryMeasure) {
    const nlohmann::json j = to_json(scene_information(cube(1, 1), lines(16'000)));
    for (const char* key : {"h_p", "h_s", "i_s", "h_j", "i_cs", "discretisation_error"}) {
        EXPECT_TRUE(j.at(key).contains("estimate")) << key;
        EXPECT_TRUE(j.at(key).contains("standard_error")) << key;
        EXPECT_TRUE(j.at(key).contains("bias")) << key;
    }
    // 1,000 lines a batch share 167 per face: 16 x 167 x 6 lines.
    EXPECT_EQ(j.at("lines").get<std::size_t>(), 16'032u);
}

}  // namespace
}  // namespace hmcr::test
