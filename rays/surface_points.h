// SPDX-License-Identifier: Apache-2.0
// Fixed stratified points on every side of a scene's patches (docs/design.md §6.9): the
// quadrature points of a point reference, independent of any mesh.
//
// Each side (the front of every patch, the back of a two-sided one) is cut into strata of about
// a = A_T / target square metres each, in its parameter space: a quad into ku x kv cells of the
// unit square (ku : kv as the quad's mean edge lengths, ku kv about A / a), a triangle into k^2
// congruent sub-triangles (k^2 about A / a); a side smaller than a is one stratum. One point
// lies in each stratum, uniform in the stratum's parameter domain, with weight
// J(u, v) x (the stratum's parameter area): the sum over a side's points of w f(p) is then an
// unbiased estimate of the integral of f over the side (a stratified, jittered quadrature), and
// exact for a constant f on triangles and parallelograms. The jitter comes from a stream keyed
// by the patch and side (and a strata seed, 0 unless asked), so the points are the same for every
// seed of the paths, thread and rank count.
#pragma once

#include <cstdint>
#include <vector>

#include "common/types.h"
#include "rays/patch.h"

namespace hmcr {

struct SurfacePoint {
    Vec3 position;
    double weight = 0;  // m^2: the quadrature weight, about the stratum's area
    std::uint32_t patch = 0;
    std::uint8_t side = kFront;
};

// The strata of one side for a target spacing of `area_per_point` m^2: (ku, kv) for a quad,
// (k, k) for a triangle (k^2 sub-triangles); each at least 1.
struct SideStrata {
    std::uint32_t ku = 1, kv = 1;
    std::uint64_t count(bool quad) const { return std::uint64_t(ku) * (quad ? kv : ku); }
};
SideStrata side_strata(const Patch& patch, double area_per_point);

// How many points stratified_points gives for `target`, without making them (for the memory
// check before the work).
std::uint64_t stratified_point_count(const PatchSet& set, std::uint64_t target);

// The points of every side, ordered by patch, front before back, then stratum. target >= 1.
// Another `strata_seed` gives another, independent jitter of the same strata.
std::vector<SurfacePoint> stratified_points(const PatchSet& set, std::uint64_t target,
                                            std::uint64_t strata_seed = 0);

}  // namespace hmcr
