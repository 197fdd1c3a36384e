// SPDX-License-Identifier: Apache-2.0
// Object error against a point reference (docs/design.md §6.9): the object error of
// studies/object_space_error.h with the reference's quadrature points (rays/surface_points.h)
// in place of a reference mesh, and the reference's own noise taken out.
//
// With w_i a point's weight, s_i the solution's Gouraud radiosity there
// (studies/solution_probe.h), B_i the mean of the reference's two seeds and v_i the variance of
// that mean (per channel, summed over channels as tr v_i), E_i the side's emission:
//
//   N = sum_i w_i (|s_i - B_i|^2 - tr v_i),   D = sum_i w_i (|B_i - E_i|^2 - tr v_i),
//   e = sqrt(max(N, 0) / D).
//
// E[|s - B_i|^2] = |s - B|^2 + tr v_i for an unbiased B_i of variance v_i, so N and D are
// unbiased for the integrals of the exact field's squared error and squared reflected
// radiosity: the reference's noise is not a floor under every error. The standard error of e
// is the delta method's, from the variances of N and D and their covariance, each point's
// noise taken as normal (var((x + n)^2) = 4 x^2 v + 2 v^2 per channel, x estimated without
// bias as (x + n)^2 - v), plus the quadrature's own variance (the points are jittered, so the
// sums are random too), estimated by taking each two neighbouring points as one stratum of two
// (collapsed strata, which overstates it a little).
#pragma once

#include <vector>

#include "radiosity/shaded_mesh.h"
#include "rays/patch.h"
#include "studies/object_space_error.h"
#include "viz/point_radiosity_file.h"
#include "viz/shaded_tracer.h"

namespace hmcr {

// A point reference ready to measure solutions against: its points, each side's emission and
// the unit normal out of each point's side.
struct PointTarget {
    PointRadiosity points;
    std::vector<Rgb> emission;
    std::vector<Vec3> normal;
};
PointTarget point_target(PointRadiosity points, const PatchSet& set);

// Parallel over the points with TBB; the result does not depend on the number of threads.
ObjectError point_object_error(const ShadedTracer& tracer, const ShadedMesh& solution,
                               const PointTarget& reference);

}  // namespace hmcr
