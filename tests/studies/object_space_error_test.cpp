// SPDX-License-Identifier: Apache-2.0
#include "studies/object_space_error.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "tests/support/shaded_grid.h"

namespace hmcr {
namespace {

using test::append;
using test::Field;
using test::grid;

// Embree's float barycentrics perturb the solution's values by about 1e-7 relative; the
// quadrature is otherwise exact for the linear fields used here.
constexpr double kTol = 1e-6;

// A linear field: channel k is coef[k][0] + coef[k][1] x + coef[k][2] y.
using Linear = std::array<std::array<double, 3>, 3>;
Field linear(const Linear& coef) {
    return [coef](const Vec3& p) {
        Rgb b;
        for (int k = 0; k < 3; ++k) b[k] = coef[k][0] + coef[k][1] * p.x() + coef[k][2] * p.y();
        return b;
    };
}
// Integral over the unit square of |field|^2: per channel, (a + b x + c y)^2 integrates to
// a^2 + b^2/3 + c^2/3 + ab + ac + bc/2.
double integral_of_square(const Linear& coef) {
    double sum = 0;
    for (const auto& [a, b, c] : coef) {
        sum += a * a + b * b / 3 + c * c / 3 + a * b + a * c + b * c / 2;
    }
    return sum;
}

const Linear kReference = {{{1, 1, 2}, {2, 0, 0}, {3, -1, 0}}};
const Linear kDifference = {{{0.5, 1, 0}, {0, 0, -1}, {0, 0.25, 0.5}}};

Linear plus(const Linear& a, const Linear& b) {
    Linear out;
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < 3; ++i) out[k][i] = a[k][i] + b[k][i];
    }
    return out;
}

TEST(ObjectSpaceError, SameFieldOnAnotherMeshIsZero) {
    const ShadedMesh ref = grid(4, 4, linear(kReference));
    const ObjectError e = object_space_error(grid(3, 2, linear(kReference), true), ref);
    EXPECT_LT(e.relative_l2, kTol);
    EXPECT_EQ(e.samples, 16u * 2 * 3 * 4);  // cells x fan triangles x 3 points x k^2
    EXPECT_EQ(e.unmatched, 0u);
    EXPECT_LT(object_space_error(ref, ref).relative_l2, kTol);
}

TEST(ObjectSpaceError, ScaledFieldGivesTheScale) {
    const double c = 0.25;
    const auto scaled = [&](const Vec3& p) { return Rgb((1 + c) * linear(kReference)(p)); };
    const ObjectError e = object_space_error(grid(5, 2, scaled), grid(4, 4, linear(kReference)));
    EXPECT_NEAR(e.relative_l2, c, kTol);
}

// With the patches' emission given, the error is relative to the reflected part B - E: a
// solution whose reflected radiosity is 1.25 times the reference's is off by 0.25, however
// bright the emitter.
TEST(ObjectSpaceError, WithEmissionItIsRelativeToTheReflectedRadiosity) {
    const double c = 0.25;
    const Rgb e(50, 40, 30);
    const auto ref_field = [&](const Vec3& p) { return Rgb(e + linear(kReference)(p)); };
    const auto sol_field = [&](const Vec3& p) { return Rgb(e + (1 + c) * linear(kReference)(p)); };
    ObjectErrorOptions o;
    o.emission = {e};  // the grid is patch 0
    const ShadedMesh ref = grid(4, 4, ref_field);
    EXPECT_NEAR(object_space_error(grid(5, 2, sol_field), ref, o).relative_l2, c, kTol);
    EXPECT_LT(object_space_error(grid(5, 2, sol_field), ref).relative_l2, c / 10);
}

TEST(ObjectSpaceError, TwoLinearFieldsMatchTheClosedForm) {
    const double expected =
        std::sqrt(integral_of_square(kDifference) / integral_of_square(kReference));
    const ShadedMesh solution = grid(3, 3, linear(plus(kReference, kDifference)), true);
    const ShadedMesh reference = grid(4, 4, linear(kReference));
    // The 3-point rule integrates the quadratic |B_sol - B_ref|^2 exactly at any k.
    for (const int k : {1, 2, 3}) {
        const ObjectError e = object_space_error(solution, reference, {k, {}, {}});
        EXPECT_NEAR(e.relative_l2, expected, kTol) << "k = " << k << ", " << e.to_string();
    }
    // The estimator integrates over the reference's surface: the roles are not symmetric.
    const double swapped = std::sqrt(integral_of_square(kDifference) /
                                     integral_of_square(plus(kReference, kDifference)));
    EXPECT_NEAR(object_space_error(reference, solution).relative_l2, swapped, kTol);
}

TEST(ObjectSpaceError, PointsAreMatchedOnTheirOwnPatch) {
    // A floor (patch 0) and, 1e-7 above it, a facing-down plate (patch 1) over part of it,
    // closer than the probe's offset: the probe must look through the wrong surface's side.
    const auto plate = [](const Field& f) {
        ShadedMesh p = grid(2, 2, f, false, 1e-7, 1, true);
        for (Vec3& x : p.points) x.head<2>() = 0.25 * Vec2::Ones() + 0.5 * x.head<2>();
        for (std::size_t i = 0; i < p.points.size(); ++i) p.point_radiosity[i] = f(p.points[i]);
        return p;
    };
    const Field floor_field = linear(kReference);
    const Field plate_field = [](const Vec3&) { return Rgb(0.5, 0.5, 0.5); };
    ShadedMesh reference = grid(4, 4, floor_field);
    append(reference, plate(plate_field));
    ShadedMesh solution = grid(3, 5, floor_field, true);
    append(solution, plate(plate_field));
    const ObjectError e = object_space_error(solution, reference);
    EXPECT_EQ(e.unmatched, 0u);
    EXPECT_LT(e.relative_l2, kTol);

    // Without the plate in the solution, its points are unmatched and count as B_sol = 0.
    const ObjectError missing = object_space_error(grid(3, 5, floor_field, true), reference);
    EXPECT_EQ(missing.unmatched, 4u * 2 * 3 * 4);
    const double plate_part = 0.25 * 0.75;  // area 0.25 times |(0.5, 0.5, 0.5)|^2
    EXPECT_NEAR(missing.relative_l2,
                std::sqrt(plate_part / (integral_of_square(kReference) + plate_part)), kTol);
}

// Two coplanar patches meeting at x = 0.5, the second a light (B 100 against 1), the reference
// holding a cell of each only 1e-8 wide along their shared edge: the tracer's float arithmetic
// puts those cells' points on the edge, where a ray may meet the other patch. They are found on
// their own patch's nearest cell: no point is unmatched, and equal fields give no error.
TEST(ObjectSpaceError, PointsAtAnEdgeBetweenPatchesAreTheirOwnPatchs) {
    const double s = 1e-8;
    const auto strip = [](double x0, double x1, int patch, double b) {
        ShadedMesh m = grid(
            1, 4, [&](const Vec3&) { return Rgb::Constant(b); }, false, 0, patch);
        for (Vec3& x : m.points) x.x() = x0 + (x1 - x0) * x.x();
        return m;
    };
    ShadedMesh reference = strip(0, 0.5 - s, 0, 1);
    append(reference, strip(0.5 - s, 0.5, 0, 1));
    append(reference, strip(0.5, 0.5 + s, 1, 100));
    append(reference, strip(0.5 + s, 1, 1, 100));
    ShadedMesh solution = strip(0, 0.5, 0, 1);
    append(solution, strip(0.5, 1, 1, 100));
    ObjectErrorOptions o;
    o.emission = {Rgb::Zero(), Rgb::Constant(99)};
    const ObjectError e = object_space_error(solution, reference, o);
    EXPECT_EQ(e.unmatched, 0u) << e.to_string();
    EXPECT_GT(e.nearest, 0u) << e.to_string();  // a guard: the rays did miss
    EXPECT_LT(e.relative_l2, kTol) << e.to_string();
}

TEST(ObjectSpaceError, DoesNotDependOnThreads) {
    const ShadedMesh solution = grid(7, 5, linear(plus(kReference, kDifference)), true);
    const ShadedMesh reference = grid(40, 40, linear(kReference));
    const double all = object_space_error(solution, reference).relative_l2;
    tbb::task_arena one(1);
    EXPECT_EQ(one.execute([&] { return object_space_error(solution, reference).relative_l2; }),
              all);
}

TEST(ObjectSpaceError, RejectsMalformedInput) {
    const ShadedMesh ref = grid(2, 2, linear(kReference));
    ShadedMesh no_patches = ref;
    no_patches.patch_id.clear();
    EXPECT_THROW(object_space_error(no_patches, ref), std::invalid_argument);
    EXPECT_THROW(object_space_error(ref, no_patches), std::invalid_argument);
    EXPECT_THROW(object_space_error(ref, ref, {0, {}, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace hmcr
