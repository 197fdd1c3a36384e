// SPDX-License-Identifier: Apache-2.0
// One stochastic Jacobi iteration (docs/design.md §3): sources frozen, rays chosen
// by unshot power, each ray refined to its receiver element and deposited there.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "radiosity/refinement.h"
#include "rays/alias_table.h"
#include "rays/ray_generator.h"

namespace hmcr {

struct ZeroSurfaces;

// The sources of one iteration, frozen (Jacobi): the leaves with unshot power, each chosen with
// probability A_l |Delta B_l| / S. Built once per iteration, for the pilot and for the rays;
// the ray generator reads the leaves as regions (rays/ray_generator.h), copied out of the
// elements so that a ray reads one small record, not a large element elsewhere.
// With a control constant beta (docs/design.md §3.11) a leaf shoots Delta B_l - beta, with
// weight A_l sum_c |Delta B_l,c - beta_c|, and the zero surfaces shoot -beta.
struct IterationSources {
    std::vector<RayRegion> regions;   // each leaf's domain and patch
    std::vector<Rgb> share;           // each leaf's (Delta B - beta) / sum_c |Delta B_c - beta_c|
    std::vector<double> strength;     // each leaf's sum_c |Delta B_c - beta_c|: weight per area
    double total = 0;                 // S
    Rgb shift = Rgb::Zero();          // beta: what the leaves' Delta B was shifted by
    bool leaves = false;              // the hierarchy's leaves (not the zero surfaces)
    Rgb max_share = Rgb::Zero();      // the largest |share| of a leaf in each channel
    std::optional<AliasTable> alias;  // none when nothing is left to shoot
    // On a higher basis (docs/design.md §3.14), each leaf's coefficients 1 .. K-1 of Delta B over
    // its strength, K - 1 in a row per region (none on the constant basis): a ray from x shoots
    // share + sum_k terms_k psi_k(x), the leaf's Delta B at x over its strength, which is then
    // sum_c sqrt(sum_k Delta b_kc^2), its root mean square.
    std::vector<Rgb> terms;
    Basis basis = Basis::constant;
    int term_count = 0;  // K - 1
    // The patches the regions name: the scene's, or with `zero` its patches and background.
    const std::vector<Patch>* patches = nullptr;

    // The sources of h's unshot power now minus beta (0: the plain iteration, bit for bit), in
    // the storage of the previous iteration's.
    void rebuild(const Hierarchy& h, const Rgb& beta = Rgb::Zero());
    // The zero surfaces, each shooting the radiosity `shot` (-beta) over its area.
    void rebuild(const ZeroSurfaces& zero, const Rgb& shot);
    // Each region's weight, A_l sum_c |share|: what the alias table and the strata deal by.
    std::span<const double> weights() const { return m_weights; }

private:
    void clear(std::size_t most);  // and makes room for `most` sources
    void add(const RayRegion& region, double area, const Rgb& shot);
    void add_with_terms(const RayRegion& region, double area, const Rgb& shot,
                        const TermSlot* slots, const PolynomialBasis& functions);
    // A source of strength `sum` shooting `unit` per strength, whose rays' share is at most
    // `most` per channel.
    void push(const RayRegion& region, double area, double sum, const Rgb& unit, const Rgb& most);
    void finish();

    std::vector<double> m_weights;  // A_l |Delta B_l|, for the alias table
};

// The rays a task of the shooting generates and traces together (a multiple of
// EmbreeScene::kPacketRays, so that chunks are whole packets); the bench's floor traces the same.
inline constexpr std::uint64_t kChunkRays = 256;

// The rays of an iteration that one process shoots: [begin, end) of its N (MPI ranks share an
// iteration; a single process shoots all of it, the default).
struct RaySlice {
    std::uint64_t begin = 0, end = UINT64_MAX;
};

// The rays of an iteration may come in parts with sources of their own (the control variate's
// zero surfaces, docs/design.md §3.11): a part's ray k has the stream key first_key + k, and
// every part deposits in the iteration's common quantum. The default: one part.
struct RayPart {
    std::uint64_t first_key = 0;
    std::optional<PowerQuantum> quantum;  // none: the part's own, from its sources
};

struct IterationOutcome {
    std::uint64_t rays = 0;    // shot by this process
    PowerQuantum quantum;      // of the whole iteration, the same for every slice
    Quanta shot_power{};       // sum of the rays' power
    Quanta escaped_power{};    // rays that left the scene
    Quanta back_face_power{};  // rays absorbed by a back face
    RefinementCounters counters;
};

// The buffers shoot_iteration fills for each batch of rays, kept by the caller from one
// iteration to the next: allocated once per solve, their pages are faulted in once (when every
// iteration allocated its own, they were a third of a Cornell box solve's page faults).
class ShootingBuffers {
public:
    ShootingBuffers();
    ~ShootingBuffers();

    struct Impl;  // defined where they are used
    Impl& impl() { return *m_impl; }

private:
    std::unique_ptr<Impl> m_impl;
};

// Fraction of the current unshot power that its receivers will reflect, estimated from `rays`
// pilot rays traced without refinement or deposits (for the ray schedule).
double reflected_fraction(const RefinementContext& ctx, const IterationSources& sources,
                          std::uint32_t iteration, std::uint64_t rays);

// The share of `rays` pilot rays from the zero surfaces, uniform over their area and on streams
// of their own, that land on a side of reflectance > 0 (docs/design.md §3.11); 1 without rays.
double zero_surfaces_seen(const RefinementContext& ctx, const ZeroSurfaces& zero,
                          std::uint64_t rays);

// Shoots the rays `slice` of the `rays` rays of iteration `iteration` and adds their deposits,
// in quanta, to the elements' received accumulators.
// `on_batch(rays_done)` is called from the calling thread between batches. Without `buffers`,
// the call allocates its own.
IterationOutcome shoot_iteration(const RefinementContext& ctx, const IterationSources& sources,
                                 std::uint32_t iteration, std::uint64_t rays, RaySlice slice = {},
                                 const std::function<void(std::uint64_t)>& on_batch = {},
                                 ShootingBuffers* buffers = nullptr, const RayPart& part = {});

// Adds `part`'s rays, power totals and counters to `whole` (both in the same quantum).
void add_part(IterationOutcome& whole, const IterationOutcome& part);

}  // namespace hmcr
