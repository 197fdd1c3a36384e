// SPDX-License-Identifier: Apache-2.0
// Object-space error of a meshing study (docs/design.md §6): the area-weighted relative L2
// difference between a solution's and the reference's Gouraud radiosity over all surfaces,
//
//   e = sqrt( int |B_sol(x) - B_ref(x)|^2 dA  /  int |B_ref(x)|^2 dA ),
//
// |.| the Euclidean norm over RGB, B the Gouraud field each ShadedMesh shows (the barycentric
// interpolation of its point radiosity over its cells' triangles, viz/cell_triangles.h, as
// rendered).
// Both meshes come from the same scene: the same patches, different subdivisions.
//
// Estimator: a fixed, deterministic quadrature over the reference's surface. Every triangle of
// every reference cell is cut into k x k congruent sub-triangles (k = subdivisions; each
// edge into k parts), and each sub-triangle is integrated with the symmetric 3-point rule
// (points at barycentric (2/3, 1/6, 1/6) and its permutations, weight area / 3), which is exact
// for quadratics. The estimate is therefore exact when B_sol - B_ref is linear on every
// reference sub-triangle (e.g. a solution and a reference showing linear fields), and otherwise
// converges as the reference is refined. The points are interior, so no ray grazes an edge.
//
// B_ref at a point comes from the reference triangle's own barycentric weights. B_sol comes from
// a ShadedTracer of the solution: a ray from delta in front of the point (along the reference
// cell's normal, delta = ten times Embree's self-hit offset, 1e-5 of the scene's bounding-box
// diagonal) back along minus the normal. The hit must be on a solution cell of the same
// patch; if a surface closer than delta is hit instead (an object resting on the floor), the
// ray is cast from behind the point instead. A point neither ray finds on its patch (one within
// the tracer's float precision of an edge to another patch, such as a light tile's in a
// ceiling) takes the Gouraud value at the closest point of its patch side's solution cells
// within delta, and is counted as `nearest`. A point with no such cell counts with B_sol = 0
// and is reported as unmatched: it means the meshes do not cover the same surfaces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "radiosity/shaded_mesh.h"
#include "rays/patch.h"
#include "viz/shaded_tracer.h"

namespace hmcr {

struct ObjectErrorOptions {
    int subdivisions = 2;  // k: each reference triangle gives k^2 sub-triangles, 3 points each
    // Emitted radiosity E of every patch (by patch id), or empty. When given, the denominator
    // integrates |B_ref - E|^2: the error is then relative to the reflected radiosity, what the
    // solver computes (E is exact in both solutions, so the numerator does not change). Without
    // it a light swamps the denominator: on the Cornell box its 0.7% of the area holds 99% of
    // the integral of |B|^2.
    std::vector<Rgb> emission;
    // The same for the backs of two-sided patches (by patch id; black for one-sided ones), or
    // empty when no patch has a back.
    std::vector<Rgb> back_emission;

    std::string to_string() const;
};

// A patch side's part of an object error's squared numerator.
struct PatchError {
    std::uint32_t patch = 0;
    std::uint8_t side = kFront;
    double share = 0;  // of the numerator; noise-corrected against a point reference
};

// The patches an ObjectError lists, the largest shares first.
inline constexpr std::size_t kLargestPatches = 10;

struct ObjectError {
    double relative_l2 = 0;  // e above; 0 when both fields are 0, +inf when only B_ref is 0
    // Its standard error from the reference's own noise, known against a point reference
    // (studies/point_error.h); NaN against a mesh reference.
    double standard_error = std::numeric_limits<double>::quiet_NaN();
    std::size_t samples = 0;    // quadrature points
    std::size_t unmatched = 0;  // points where the solution shows no surface of the same patch
    std::size_t nearest = 0;    // points the rays missed, found on their patch's nearest cell
    // Points on a side the solution has no cell of at all, where the other side of the patch
    // has cells: a back the solution's light never reached, whose radiosity is its emission E
    // (0 but for a glowing back). They count with B_sol = E, not as unmatched.
    std::size_t unlit = 0;
    std::vector<PatchError> largest;  // at most kLargestPatches, largest share first

    std::string to_string() const;
};

// The squared error of each patch side, summed as an object error integrates, and the sides
// holding the most of it.
class SideErrors {
public:
    void add(std::uint32_t patch, std::uint8_t side, double squared_error);
    // At most kLargestPatches sides with their share of `total`, largest first.
    std::vector<PatchError> largest(double total) const;

private:
    std::vector<double> m_sum;  // by 2 * patch + side
};

// Throws std::invalid_argument on malformed meshes (patch_id missing for some cell) or options.
// Parallel over the reference with TBB; the result does not depend on the number of threads.
ObjectError object_space_error(const ShadedMesh& solution, const ShadedMesh& reference,
                               const ObjectErrorOptions& options = {});
// The same with a tracer of the solution already built (a study renders it too).
ObjectError object_space_error(const ShadedTracer& solution_tracer, const ShadedMesh& solution,
                               const ShadedMesh& reference, const ObjectErrorOptions& options = {});

}  // namespace hmcr
