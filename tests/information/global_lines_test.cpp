// SPDX-License-Identifier: Apache-2.0
// Global lines (information/channel_samples.h): the form factors and measures of the empty cube
// against their exact values, agreement with local lines on the Cornell box, and the same
// reproducibility and invariance as local lines.
//
// Tolerances: z = 4 standard errors (binomial for a form factor, given the crossings of its
// patch; batch means for the measures), plus Paninski's bound where the plug-in bias matters
// (tests/support/information.h).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "common/error.h"
#include "information/channel_samples.h"
#include "information/form_factors.h"
#include "information/scene_information.h"
#include "tests/support/analytic.h"
#include "tests/support/information.h"
#include "tests/support/statistics.h"

namespace hmcr::test {
namespace {

LineOptions lines(LineMethod method, std::uint64_t n, std::uint64_t seed = 11) {
    return {method, n, 16, seed};
}

// Given that n lines cross face i, their rays from i are independent cosine rays, so each
// F_ij is binomial with the realised n. Every line through the box crosses two faces.
TEST(GlobalLines, CubeFormFactorsMatchExactValues) {
    const PatchSet set = cube_patches(1, 1);
    const EmbreeScene scene(set.patches);
    const ChannelSamples samples =
        trace_global_lines(set, scene, lines(LineMethod::global, 400'000));
    const SparseFormFactors f = form_factors(samples);
    const EmptyCube exact = empty_cube();
    for (std::size_t i = 0; i < 6; ++i) {
        ASSERT_GT(f.rays[i], 10'000u);
        for (std::size_t j = 0; j < 6; ++j) {
            const double dot = set.patches[i].normal.dot(set.patches[j].normal);
            const double f_ij = i == j ? 0.0 : dot < -0.5 ? exact.opposite : exact.adjacent;
            const double se = std::sqrt(std::max(f_ij * (1 - f_ij), 1e-12) / double(f.rays[i]));
            EXPECT_TRUE(within_standard_errors("F_" + std::to_string(i) + std::to_string(j),
                                               f(i, j), f_ij, se));
        }
    }
    EXPECT_EQ(samples.samples() % 2, 0u);  // crossings come in pairs on a closed convex box
}

TEST(GlobalLines, EmptyCubeMatchesExactMeasures) {
    const EmptyCube exact = empty_cube();
    const auto [m, bias, open] =
        measure_channel(cube_patches(1, 1), lines(LineMethod::global, 1'000'000));
    EXPECT_NEAR(m.h_p.estimate, exact.h_p, 1e-12);
    EXPECT_TRUE(
        within_standard_errors("H_S", m.h_s.estimate, exact.h_s, m.h_s.standard_error, bias));
    EXPECT_TRUE(
        within_standard_errors("I_S", m.i_s.estimate, exact.i_s, m.i_s.standard_error, bias));
    EXPECT_EQ(m.patches_unsampled, 0u);
    EXPECT_LT(m.samples_open, m.samples / 10'000);  // only rays slipping through an edge
}

// The two methods sample the same distribution of rays, so their measures agree. I^c_S is
// unbiased in both; H_S and I_S carry plug-in biases of one sign, each within its bound, so
// their difference is within the larger bound. The Cornell box has occlusion and an open side.
TEST(GlobalLines, AgreeWithLocalLinesOnTheCornellBox) {
    const PatchSet set = cornell_patches();
    const auto [local, local_bias, local_open] =
        measure_channel(set, lines(LineMethod::local, 4'000'000));
    const auto [global, global_bias, global_open] =
        measure_channel(set, lines(LineMethod::global, 4'000'000));
    const double bias = std::max(local_bias, global_bias);
    const auto agree = [&](const char* what, const InformationMeasures::Value& l,
                           const InformationMeasures::Value& g, double b) {
        return within_standard_errors(what, g.estimate, l.estimate,
                                      std::hypot(l.standard_error, g.standard_error), b);
    };
    EXPECT_TRUE(agree("H_S", local.h_s, global.h_s, bias));
    EXPECT_TRUE(agree("I_S", local.i_s, global.i_s, bias));
    EXPECT_TRUE(agree("I^c_S", local.i_cs, global.i_cs, 0));
    EXPECT_TRUE(
        agree("I^c_S - I_S", local.discretisation_error, global.discretisation_error, bias));
    // The open share of rays (out of the front, onto back faces) is the same quantity too.
    EXPECT_TRUE(
        within_standard_errors("open share", global_open.mean, local_open.mean,
                               std::hypot(global_open.standard_error, local_open.standard_error)));
    EXPECT_EQ(global.patches_unsampled, 0u);
}

TEST(GlobalLines, ResultsDoNotDependOnThreadCount) {
    const PatchSet set = cornell_patches();
    const EmbreeScene scene(set.patches);
    const LineOptions options = lines(LineMethod::global, 50'000);
    const ChannelSamples many = trace_global_lines(set, scene, options);
    const ChannelSamples one = [&] {
        const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        return trace_global_lines(set, scene, options);
    }();
    EXPECT_EQ(many.first, one.first);
    EXPECT_EQ(many.target, one.target);
    EXPECT_EQ(many.log_kernel_sum, one.log_kernel_sum);
    EXPECT_EQ(many.log_kernel_count, one.log_kernel_count);
}

TEST(GlobalLines, ScalingChangesNoMeasure) {
    const auto options = lines(LineMethod::global, 200'000);
    const InformationMeasures a = scene_information(cube_patches(1, 2), options);
    const InformationMeasures b = scene_information(cube_patches(4, 2), options);
    // The bounding sphere scales with the scene, so the same lines cross the same patches. A
    // power of two keeps even Embree's float arithmetic exact (at a scale of 3, 4 of 254,000
    // rays that graze an edge land differently).
    EXPECT_NEAR(a.i_s.estimate, b.i_s.estimate, 1e-9);
    EXPECT_NEAR(a.i_cs.estimate, b.i_cs.estimate, 1e-9);
    EXPECT_EQ(a.samples, b.samples);
}

TEST(GlobalLines, UnknownMethodIsNamed) {
    EXPECT_EQ(parse_line_method("global"), LineMethod::global);
    EXPECT_EQ(parse_line_method("local"), LineMethod::local);
    try {
        parse_line_method("globl");
        FAIL() << "no throw";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'globl'"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace hmcr::test
