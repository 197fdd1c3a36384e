// Scene information measures (SPEC section 7) against exact values and known properties.
//
// Tolerances: z = 4 batch-means standard errors, plus, where the plug-in entropy's bias
// matters, Paninski's bound (Neural Computation 2003): a row of K reachable patches estimated
// from n rays has 0 <= H - E[H_hat] <= log2(1 + (K - 1) / n). H_S is an a-weighted mean of row
// entropies and the rest of I_S is linear in F, so I_S is biased upward by at most that much
// with n the fewest rays of any patch and K the patch count.
#include "studies/scene_information.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/support/analytic.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

PatchSet cube(double size, int n) {
    return build_patch_set(make_patch_mesh(
        inward_box(Vec3::Zero(), Vec3::Constant(size), n, Rgb::Constant(0.5), Rgb::Zero())));
}

PatchSet sphere(int level) {
    return build_patch_set(make_patch_mesh(inward_icosphere(level, 1.0, Rgb::Constant(0.5))));
}

LocalLineOptions lines(std::uint64_t n, std::uint64_t seed = 7) { return {n, 16, seed}; }

// Paninski's bound on the plug-in bias of H_S (downward) and I_S (upward), in bits.
double plug_in_bias_bound(const PatchSet& set, const LocalLineOptions& options) {
    const auto counts = local_line_counts(set, options);
    const double n = double(*std::min_element(counts.begin(), counts.end()));
    return std::log2(1 + double(set.patches.size() - 1) / n);
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

double plogp(double p) { return p * std::log2(p); }

TEST(SceneInformation, CubeFormFactorsMatchExactValues) {
    const PatchSet set = cube(1, 1);
    const EmbreeScene scene(set.patches);
    const SparseFormFactors f = form_factors(trace_local_lines(set, scene, lines(320'000)));
    const double opposite = parallel_rectangles(1, 1, 1);
    const double adjacent = perpendicular_rectangles(1, 1, 1);
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
    const double opposite = parallel_rectangles(1, 1, 1);
    const double adjacent = perpendicular_rectangles(1, 1, 1);
    EXPECT_NEAR(opposite, 0.19982, 5e-6);
    EXPECT_NEAR(adjacent, 0.20004, 5e-6);
    EXPECT_NEAR(opposite + 4 * adjacent, 1.0, 1e-9);  // row sum of a closed scene

    const double h_p = std::log2(6.0);
    const double h_s = -(plogp(opposite) + 4 * plogp(adjacent));  // every row alike
    const double i_s = h_p - h_s;

    const PatchSet set = cube(1, 1);
    const LocalLineOptions options = lines(1'600'000);
    const InformationMeasures m = scene_information(set, options);
    // 266,672 rays per face: the bias bound is 2.7e-5 bits, about 2 standard errors.
    const double bias = plug_in_bias_bound(set, options);
    EXPECT_NEAR(m.h_p.estimate, h_p, 1e-12);
    EXPECT_TRUE(within_standard_errors("H_S", m.h_s.estimate, h_s, m.h_s.standard_error, bias));
    EXPECT_TRUE(within_standard_errors("I_S", m.i_s.estimate, i_s, m.i_s.standard_error, bias));
    EXPECT_TRUE(
        within_standard_errors("H_J", m.h_j.estimate, h_p + h_s, m.h_j.standard_error, bias));
    EXPECT_GT(m.i_s.standard_error, 0.0);
    EXPECT_EQ(m.lines, 1'600'032u);
    EXPECT_LT(m.lines_missed, m.lines / 10'000);
}

TEST(SceneInformation, ScalingChangesNoMeasure) {
    const InformationMeasures a = scene_information(cube(1, 1), lines(200'000));
    const InformationMeasures b = scene_information(cube(3, 1), lines(200'000));
    // Same seed, scale-equivariant sampling: the same lines hit the same patches.
    EXPECT_NEAR(a.i_s.estimate, b.i_s.estimate, 1e-9);
    EXPECT_NEAR(a.i_cs.estimate, b.i_cs.estimate, 1e-9);
    EXPECT_EQ(a.lines_missed, b.lines_missed);
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
    const LocalLines many = trace_local_lines(set, scene, lines(100'000));
    const LocalLines one = [&] {
        const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        return trace_local_lines(set, scene, lines(100'000));
    }();
    EXPECT_EQ(many.target, one.target);
    EXPECT_EQ(many.log_kernel_sum, one.log_kernel_sum);
    EXPECT_EQ(many.log_kernel_count, one.log_kernel_count);
}

// The interior of a sphere has A_T F(x, y) = 1, so I^c_S = 0. The tessellation's I^c_S is a
// KL divergence (>= 0) that falls with the faces' size; the stated bound is (h / R)^2 for the
// longest edge h (measured: 0.55, 0.62, 0.73 (h / R)^2 at levels 1, 2, 3).
TEST(SceneInformation, TessellatedSphereHasLittleContinuousInformation) {
    const PatchSet coarse = sphere(2), fine = sphere(3);
    const InformationMeasures c = scene_information(coarse, lines(1'000'000));
    const InformationMeasures f = scene_information(fine, lines(1'000'000));
    for (const auto* s : {&coarse, &fine}) {
        const InformationMeasures& m = s == &coarse ? c : f;
        const double h = longest_edge(*s);
        EXPECT_TRUE(
            within_standard_errors("I^c_S", m.i_cs.estimate, 0.0, m.i_cs.standard_error, h * h))
            << "h = " << h;
    }
    // Refinement: |I^c_S| decreases, by more than the combined errors.
    EXPECT_LT(f.i_cs.estimate + kZ * (f.i_cs.standard_error + c.i_cs.standard_error),
              c.i_cs.estimate);
}

// H_S tends to H_P: H_P - H_S = I_S <= I^c_S, with the plug-in bias of I_S added.
TEST(SceneInformation, TessellatedSphereVisibilityEntropyNearPositional) {
    const PatchSet set = sphere(2);
    const LocalLineOptions options = lines(2'000'000);
    const InformationMeasures m = scene_information(set, options);
    const double bias = plug_in_bias_bound(set, options);  // 0.07 bits at 6,200 rays a patch
    const double se = m.h_s.standard_error + m.i_cs.standard_error;
    EXPECT_LE(m.h_p.estimate - m.h_s.estimate, m.i_cs.estimate + bias + kZ * se);
    EXPECT_LT(m.h_p.estimate - m.h_s.estimate, 0.02 * m.h_p.estimate);
}

TEST(SceneInformation, RefiningDoesNotLowerMutualInformation) {
    const PatchSet coarse = cube(1, 1), fine = cube(1, 2);
    const LocalLineOptions options = lines(1'600'000);
    const InformationMeasures c = scene_information(coarse, options);
    const InformationMeasures f = scene_information(fine, options);
    // The plug-in bias raises I_S, more so for more patches: subtract it from the finer one.
    const double bias = plug_in_bias_bound(fine, options);
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

TEST(SceneInformation, JsonHasEveryMeasure) {
    const nlohmann::json j = to_json(scene_information(cube(1, 1), lines(16'000)));
    for (const char* key : {"h_p", "h_s", "i_s", "h_j", "i_cs", "discretisation_error"}) {
        EXPECT_TRUE(j.at(key).contains("estimate")) << key;
        EXPECT_TRUE(j.at(key).contains("standard_error")) << key;
    }
    // 1,000 lines a batch share 167 per face: 16 x 167 x 6 lines.
    EXPECT_EQ(j.at("lines").get<std::size_t>(), 16'032u);
}

}  // namespace
}  // namespace hmcr::test
