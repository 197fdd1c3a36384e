// One stochastic Jacobi iteration (SPEC section 3, steps 2-6): sources frozen, rays chosen
// by unshot power, each ray refined to its receiver element and deposited there.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "radiosity/alias_table.h"
#include "radiosity/refinement.h"

namespace hmcr {

// The sources of one iteration, frozen (Jacobi): the leaves with unshot power, each chosen with
// probability A_l |Delta B_l| / S. Built once per iteration, for the pilot and for the rays.
struct IterationSources {
    std::vector<const Element*> leaves;
    double total = 0;                // S
    std::optional<AliasTable> alias;  // none when nothing is left to shoot

    explicit IterationSources(const Hierarchy& h);
    const Element& pick(double xi) const { return *leaves[alias->sample(xi)]; }
};

struct IterationOutcome {
    std::uint64_t rays = 0;
    Rgb shot_power = Rgb::Zero();       // sum of the rays' power
    Rgb escaped_power = Rgb::Zero();    // rays that left the scene
    Rgb back_face_power = Rgb::Zero();  // rays absorbed by a back face
    RefinementCounters counters;
};

// Fraction of the current unshot power that its receivers will reflect, estimated from `rays`
// pilot rays traced without refinement or deposits (for the ray schedule).
double reflected_fraction(const RefinementContext& ctx, const IterationSources& sources,
                          std::uint32_t iteration, std::uint64_t rays);

// Shoots `rays` rays of iteration `iteration` and adds their deposits to the elements'
// received accumulators, in ray order so the sums do not depend on the thread count.
// `on_batch(rays_done)` is called from the calling thread between batches.
IterationOutcome shoot_iteration(const RefinementContext& ctx, const IterationSources& sources,
                                 std::uint32_t iteration, std::uint64_t rays,
                                 const std::function<void(std::uint64_t)>& on_batch = {});

}  // namespace hmcr
