// SPDX-License-Identifier: Apache-2.0
// Point references (docs/design.md §6.9): each point's estimate within its own standard error of
// the exact radiosity (the furnace, the plates), the object error against points unbiased where
// a mesh reference reports its own floor, the same bits for any thread count.
#include "studies/point_reference.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <tuple>

#include "studies/object_space_error.h"
#include "studies/point_error.h"
#include "studies/reference_resolution.h"
#include "studies/solution_probe.h"
#include "tests/support/analytic.h"
#include "tests/support/shaded_grid.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// Two-sided normal quantile of 1e-3 / comparisons (Bonferroni), by bisection on erfc.
double bonferroni_z(double comparisons) {
    double lo = 0, hi = 10;
    for (int i = 0; i < 100; ++i) {
        const double z = 0.5 * (lo + hi);
        (std::erfc(z / std::sqrt(2.0)) > 1e-3 / comparisons ? lo : hi) = z;
    }
    return hi;
}

Scene scene_of(PatchMesh mesh, const std::string& name) {
    Scene s;
    s.name = name;
    s.mesh = std::move(mesh);
    return s;
}

PointReferenceOptions small(std::uint64_t points, std::uint64_t paths) {
    PointReferenceOptions o;
    o.points = points;
    o.paths = paths;
    return o;
}

// B on the plates' receiver, 1 m above the unit emitter (E = 1), at (x, y): rho E F(p).
double plates_b(const Vec3& p, double rho) {
    return rho * point_to_parallel_rectangle(-p.x(), 1 - p.x(), -p.y(), 1 - p.y(), 1);
}

// Each point of each seed is a hypothesis test against the exact value, with the estimate's
// own standard error; Bonferroni over every point, seed and channel.
template <class Exact>
void expect_every_point(const PointRadiosity& r, Exact exact) {
    const double z = bonferroni_z(2.0 * 3 * double(r.points.size()));
    std::size_t failed = 0;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const Rgb b = exact(r.points[i]);
        for (int s = 0; s < 2; ++s) {
            for (int c = 0; c < 3; ++c) {
                const double se = std::sqrt(r.variance[s][i][c]);
                if (std::abs(r.radiosity[s][i][c] - b[c]) > z * se) ++failed;
            }
        }
    }
    EXPECT_EQ(failed, 0u) << "points off by more than " << z << " standard errors";
}

// The noise falls as one over the root of the paths: twice the target needs four times the paths.
TEST(PointReference, ThePathsForTheTargetNoiseScaleAsItsSquare) {
    EXPECT_EQ(paths_for_target_noise(2 * kTargetNoise, 64), 256u);
    EXPECT_EQ(paths_for_target_noise(kTargetNoise, 64), 64u);
    EXPECT_EQ(paths_for_target_noise(0.24073847049632754, 64), 1484u);  // the office's, results.md
}

TEST(PointReference, TheFurnaceIsExactAtEveryPoint) {
    Scene furnace = load_scene("furnace");
    furnace.views.clear();  // the points alone
    // Russian roulette makes a path's estimate skewed: enough paths for the mean's normality.
    const PointReference ref = compute_point_reference(furnace, small(200, 1024));
    ASSERT_GE(ref.points.points.size(), 200u);
    // B = E / (1 - rho) = 2 W/m^2; a path is cut after 64 bounces, a bias of 0.5^65 E / 0.5.
    expect_every_point(ref.points, [](const SurfacePoint&) { return Rgb::Constant(2); });
    EXPECT_TRUE(
        within_standard_errors("seed check", ref.report.seed_check, 0, ref.report.seed_check_se));
}

TEST(PointReference, ThePlatesMatchTheirFormFactorAtEveryPoint) {
    const Scene plates = scene_of(unit_plates(0.5), "plates");
    const PointReference ref = compute_point_reference(plates, small(800, 128));
    std::size_t emitter = 0;
    for (std::size_t i = 0; i < ref.points.points.size(); ++i) {
        if (ref.points.points[i].patch != 0) continue;
        ++emitter;  // rho = 0: B = E exactly, with no variance
        for (int s = 0; s < 2; ++s) {
            EXPECT_TRUE((ref.points.radiosity[s][i] == 1.0).all());
            EXPECT_TRUE((ref.points.variance[s][i] == 0.0).all());
        }
    }
    EXPECT_EQ(emitter, 400u);
    expect_every_point(ref.points, [](const SurfacePoint& p) {
        return p.patch == 0 ? Rgb::Constant(1) : Rgb::Constant(plates_b(p.position, 0.5));
    });
    EXPECT_TRUE(
        within_standard_errors("seed check", ref.report.seed_check, 0, ref.report.seed_check_se));
}

TEST(PointReference, TheSameBitsForAnyThreadCount) {
    const Scene plates = scene_of(unit_plates(0.5), "plates");
    PointReferenceOptions one = small(200, 16);
    one.threads = 1;
    const PointReference a = compute_point_reference(plates, one);
    const PointReference b = compute_point_reference(plates, small(200, 16));
    for (int s = 0; s < 2; ++s) {
        ASSERT_EQ(a.points.radiosity[s].size(), b.points.radiosity[s].size());
        for (std::size_t i = 0; i < a.points.radiosity[s].size(); ++i) {
            EXPECT_TRUE((a.points.radiosity[s][i] == b.points.radiosity[s][i]).all());
            EXPECT_TRUE((a.points.variance[s][i] == b.points.variance[s][i]).all());
        }
    }
}

// The plates' exact field on an n x n grid of the receiver (facing down at z = 1) and the
// emitter as one cell of B = E = 1: a Gouraud solution whose only error is its interpolation.
ShadedMesh plates_solution(int n) {
    ShadedMesh m = grid(
        1, 1, [](const Vec3&) { return Rgb::Constant(1); }, false, 0, 0);
    append(m, grid(
                  n, n, [](const Vec3& p) { return Rgb::Constant(plates_b(p, 0.5)); }, false, 1, 1,
                  true));
    return m;
}

// The squared-error integral of plates_solution(n) against the exact field, over the receiver's
// reflected radiosity, by a midpoint rule fine enough to be exact to the digits compared.
double exact_plates_error(int n) {
    const ShadedMesh m = plates_solution(n);
    const int q = 600;
    double num = 0, den = 0;
    for (int j = 0; j < q; ++j) {
        for (int i = 0; i < q; ++i) {
            const double x = (i + 0.5) / q, y = (j + 0.5) / q;
            // The Gouraud value: facing down, a cell's corners run d, c, b, a (a at (i, j), b
            // along x, c opposite a, d along y), so its fan from d splits it along d-b.
            const double cx = x * n, cy = y * n;
            const int ci = std::min(int(cx), n - 1), cj = std::min(int(cy), n - 1);
            const double fx = cx - ci, fy = cy - cj;
            const auto at = [&](int u, int v) {
                return plates_b(Vec3(double(u) / n, double(v) / n, 1), 0.5);
            };
            const double va = at(ci, cj), vb = at(ci + 1, cj), vc = at(ci + 1, cj + 1),
                         vd = at(ci, cj + 1);
            const double g = fx + fy >= 1 ? vc + (1 - fx) * (vd - vc) + (1 - fy) * (vb - vc)
                                          : va + fx * (vb - va) + fy * (vd - va);
            const double e = plates_b(Vec3(x, y, 1), 0.5);
            num += 3 * (g - e) * (g - e);
            den += 3 * e * e;
        }
    }
    return std::sqrt(num / den);
}

// The failure a mesh reference gives: a solution finer than it is measured against the
// reference's own interpolation error (a floor), while the point reference measures the
// solution's real error, within its standard error.
TEST(PointReference, AFinerSolutionIsMeasuredWhereAMeshReferenceReportsAFloor) {
    const Scene plates = scene_of(unit_plates(0.5), "plates");
    const PointTarget points = point_target(
        compute_point_reference(plates, small(2000, 256)).points, build_patch_set(plates.mesh));
    const ShadedMesh fine = plates_solution(32), coarse = plates_solution(2);
    ObjectErrorOptions reflected;
    reflected.emission = {Rgb::Constant(1), Rgb::Zero()};
    const double fine_true = exact_plates_error(32), coarse_true = exact_plates_error(2);
    ASSERT_GT(coarse_true, 20 * fine_true);

    // Against the coarse mesh the fine solution seems as wrong as the coarse mesh is.
    const ObjectError against_mesh = object_space_error(fine, coarse, reflected);
    EXPECT_GT(against_mesh.relative_l2, 0.5 * coarse_true);
    // Against the points, each is measured as what it is.
    const ObjectError fine_e = point_object_error(ShadedTracer(fine), fine, points);
    const ObjectError coarse_e = point_object_error(ShadedTracer(coarse), coarse, points);
    EXPECT_TRUE(
        within_standard_errors("fine", fine_e.relative_l2, fine_true, fine_e.standard_error));
    EXPECT_TRUE(within_standard_errors("coarse", coarse_e.relative_l2, coarse_true,
                                       coarse_e.standard_error));
    EXPECT_LT(fine_e.relative_l2 + kZ * fine_e.standard_error, 0.25 * coarse_true);
    EXPECT_EQ(fine_e.samples, points.points.points.size());
    EXPECT_EQ(fine_e.unmatched, 0u);
    // The receiver holds the whole error.
    ASSERT_FALSE(coarse_e.largest.empty());
    EXPECT_EQ(coarse_e.largest[0].patch, 1u);
    EXPECT_NEAR(coarse_e.largest[0].share, 1.0, 1e-12);
}

// A solution off by c on a strip narrower than the strata (the quadrature's hardest case: its
// points land in the strip or not), against exact, noiseless values: the standard error is the
// quadrature's alone, and must cover the estimate's scatter over independent point sets.
TEST(PointReference, TheStandardErrorCoversTheQuadratureOfAStepNarrowerThanItsStrata) {
    const PatchSet set =
        build_patch_set(make_patch_mesh({axis_rectangle(2, 0, {0, 0}, {1, 1}, true)}));
    constexpr double kLeft = 0.5, kRight = 0.5 + 1.0 / 64, kStep = 2.0;
    ShadedMesh step;
    for (const auto& [x0, x1, b] :
         {std::tuple(0.0, kLeft, 1.0), std::tuple(kLeft, kRight, 1 + kStep),
          std::tuple(kRight, 1.0, 1.0)}) {
        // Each cell its own four points: the step does not blend into its neighbours.
        for (const Vec3& p : {Vec3(x0, 0, 0), Vec3(x1, 0, 0), Vec3(x1, 1, 0), Vec3(x0, 1, 0)}) {
            step.connectivity.push_back(std::int64_t(step.points.size()));
            step.points.push_back(p);
            step.point_radiosity.push_back(Rgb::Constant(b));
        }
        step.offsets.push_back(std::int64_t(step.connectivity.size()));
        step.patch_id.push_back(0);
        step.side.push_back(kFront);
        step.element_area.push_back(x1 - x0);
    }
    const ShadedTracer tracer(step);
    // N = 3 c^2 (kRight - kLeft) exactly (three channels), D = 3.
    const double truth = kStep * std::sqrt(kRight - kLeft);
    const double z = bonferroni_z(6);
    for (std::uint64_t target : {400, 900, 1600, 2500, 3600, 4900}) {
        PointRadiosity exact;
        exact.points = stratified_points(set, target);
        for (int s = 0; s < 2; ++s) {
            exact.radiosity[s].assign(exact.points.size(), Rgb::Constant(1));
            exact.variance[s].assign(exact.points.size(), Rgb::Zero());
        }
        const ObjectError e = point_object_error(tracer, step, point_target(exact, set));
        EXPECT_GT(e.standard_error, 0) << target;
        EXPECT_TRUE(within_standard_errors("the step at " + std::to_string(target) + " points",
                                           e.relative_l2, truth, e.standard_error, 0, z));
    }
}

TEST(ReferenceResolution, TheFinerShareIsTheAreaOfLeavesBelowHalfTheReferencesElements) {
    const auto zero = [](const Vec3&) { return Rgb::Zero(); };
    const ReferenceResolution mesh = ReferenceResolution::of_mesh(grid(4, 4, zero));
    // The reference's elements are 1/16 m^2: a leaf is finer below 1/32.
    EXPECT_EQ(mesh.finer_share(grid(8, 4, zero)), 0.0);  // leaves of 1/32
    EXPECT_EQ(mesh.finer_share(grid(8, 8, zero)), 1.0);  // leaves of 1/64
    // Eight cells of 1/64 beside eight of 1/16.
    ShadedMesh half = grid(4, 4, zero);
    for (std::size_t c = 0; c < 8; ++c) half.element_area[c] = 1.0 / 64;
    EXPECT_NEAR(mesh.finer_share(half), (8.0 / 64) / (8.0 / 64 + 8.0 / 16), 1e-12);
    // A side the reference does not cover does not count.
    ShadedMesh elsewhere = grid(8, 8, zero, false, 0, 3);
    EXPECT_EQ(mesh.finer_share(elsewhere), 0.0);

    PointRadiosity points;
    for (int i = 0; i < 100; ++i) points.points.push_back({Vec3::Zero(), 0.01, 0, kFront});
    const ReferenceResolution spaced = ReferenceResolution::of_points(points);
    EXPECT_EQ(spaced.finer_share(grid(10, 10, zero)), 0.0);  // 0.01 each: one point a leaf
    EXPECT_EQ(spaced.finer_share(grid(20, 20, zero)), 1.0);  // 0.0025 < 0.005
}

}  // namespace
}  // namespace hmcr::test
