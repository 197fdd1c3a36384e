// SPDX-License-Identifier: Apache-2.0
// The constant control variate of the shooting (docs/design.md §3.11): each iteration shoots
// Delta B - beta from every surface, the surfaces of radiosity 0 a lit side may see included,
// and adds rho beta to every side exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "radiosity/hierarchy.h"
#include "rays/patch.h"

namespace hmcr {

// The surfaces of radiosity 0 that shoot -beta: the backs of one-sided patches that a side
// with rho > 0 may see, and the background: the faces of the scene's bounding box through
// which such a side may see out, facing inward.
struct ZeroSurfaces {
    // The scene's patches, then the background box's faces (their normals point inward):
    // what the ray generator reads the sources' corners from.
    std::vector<Patch> patches;
    std::size_t scene_patches = 0;     // the first patches are the scene's
    std::vector<std::uint32_t> backs;  // one-sided patches whose back shoots
    double area = 0;                   // of the backs and the background faces
    // The share of their rays that land on a side of reflectance > 0, estimated by pilot rays
    // (zero_surfaces_seen, radiosity/shooting.h); it only steers the choice of beta.
    double seen = 1;

    explicit ZeroSurfaces(const PatchSet& ps);
    bool has_background() const { return patches.size() > scene_patches; }
};

// The constant per channel that minimises the estimator's variance as §3.11 models it,
// (P + sqrt(seen) z |beta|)^2, P = sum_l A_l |Delta B_l - beta| over every leaf of every side and
// z the zero surfaces' area: the area-weighted median of Delta B, the zero surfaces at 0 with
// the area sqrt(seen) z.
Rgb control_constant(const Hierarchy& h, const ZeroSurfaces& zero);

// How many of an iteration's `rays` the zero surfaces shoot, given the power the sides and they
// shoot: the share sqrt(seen) Z / (S + sqrt(seen) Z), which minimises the modelled variance, but
// at least 1% of their share of the power and at least one ray (§3.11).
std::uint64_t zero_surface_rays(std::uint64_t rays, double sides_power, double zero_power,
                                double seen);

// Adds rho_side beta to the radiosity and the unshot radiosity of every element of every side.
void add_constant(Hierarchy& h, const Rgb& beta);

// The faces of the scene's bounding box, facing inward and moved out by 10^-5 of its
// diagonal, through which a side of reflectance > 0 may see out: all but those that patches in
// their plane cover (assumed not to overlap) with no side of reflectance > 0 turned outward.
std::vector<Patch> background_faces(const PatchSet& ps);

}  // namespace hmcr
