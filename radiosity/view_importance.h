// SPDX-License-Identifier: Apache-2.0
// View importance (docs/design.md §3.12): how much each side's radiosity matters to the scene's
// views, directly (the pixels that see it) and through the light it reflects onto what they see.
// Solved as the adjoint of radiosity on the patches; it weighs the oracles' link values so that
// a refining solve puts its elements where the views look.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/ranks.h"
#include "meshes/view.h"
#include "radiosity/solver_options.h"
#include "rays/embree_scene.h"
#include "rays/patch.h"

namespace hmcr {

// The share of the views' pixels whose ray through the pixel centre first meets each side
// (index 2 * patch + side; a one-sided patch seen from behind is no side). Sums to at most 1:
// the rest of the pixels see nothing.
std::vector<double> view_pixel_shares(const PatchSet& patches, const EmbreeScene& scene,
                                      std::span<const View> views);

struct ViewImportance {
    // Per side (2 * patch + side) and channel: rho I / mean(I), what replaces the receiver's
    // reflectance in a link's weight w_ij (1 x rho where the importance is the scene's mean).
    std::vector<Rgb> receiver_weights;
    // Per side and channel: the importance I itself (K / rho; 0 where rho is 0).
    std::vector<Rgb> importance;
    // The importance solve's own (it shoots as many rays as it is given).
    std::uint64_t rays = 0;
    std::size_t iterations = 0;
    double seconds = 0;
};

// The importance of every side for `views`: the direct importance V = pixel share / area,
// propagated by a radiosity solve on the patches (no oracle, no refinement) of K = rho I,
// K = rho V + rho F K, from `rays` rays (the refining pass's) keyed apart from the radiance
// solve's, its other settings the radiance solve's `options`. Throws
// InputError when the views see no reflecting side. The same bits for any thread or rank count.
ViewImportance solve_view_importance(const PatchSet& patches, const EmbreeScene& scene,
                                     std::span<const View> views, const SolverOptions& options,
                                     std::uint64_t rays, const Ranks& ranks = Ranks::single());

}  // namespace hmcr
