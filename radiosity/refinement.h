// SPDX-License-Identifier: Apache-2.0
// Per-ray hierarchical refinement (docs/design.md §3): the descent from the root link to
// the receiver element that takes the ray's power.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/radix_sort.h"
#include "oracles/oracle.h"
#include "radiosity/clusters.h"
#include "radiosity/hierarchy.h"
#include "radiosity/leaf_index.h"
#include "radiosity/link_cache.h"
#include "radiosity/solver_options.h"
#include "rays/embree_scene.h"

namespace hmcr {

class SequenceCursors;

// What every descent of a solve shares. Built with designated initialisers (.oracle = ...).
struct RefinementContext {
    Hierarchy& hierarchy;
    const Oracle& oracle;
    const EmbreeScene& scene;
    double threshold = 0;  // epsilon * Phi_max: a link is accepted when its value is below
    int lines = 10;        // N_s
    std::uint64_t seed = 0;
    // The line-based oracles' geometric factors (never power's); none: recomputed every time.
    LinkCache* cache = nullptr;
    // A fixed mesh's leaves: deposit on the leaf at the hit, ask no oracle; none: refine.
    const LeafIndex* fixed_leaves = nullptr;
    LinkWeight link_weight = LinkWeight::unshot;  // w_ij from the source's Delta B or B
    RaySequence sequence = RaySequence::random;   // the shooting rays' uniforms (rays/sobol.h)
    // On a fixed mesh with the Sobol sequence, each source leaf's sequence through the pass
    // (radiosity/sequence_cursors.h), which each iteration's shot advances; none: one an iteration.
    SequenceCursors* sequence_cursors = nullptr;
    // On a fixed mesh, whether a line that lands also shoots its receiver leaf's unshot power
    // back to its source (docs/design.md §3.13); never in a refining pass.
    Bidirectional bidirectional = Bidirectional::no;
    ClusterTree* clusters = nullptr;  // descents start at its top (docs/design.md §2.7); none
    // Per side (SideRef::value), what a link's weight takes for the receiver's reflectance:
    // rho I / mean(I) under view importance (§3.12); empty: the reflectance itself.
    std::span<const Rgb> receiver_weights{};
};

struct RefinementCounters {
    std::uint64_t oracle_calls = 0;        // link decisions
    std::uint64_t oracle_evaluations = 0;  // geometric factors computed (cache misses)
    std::uint64_t cache_hits = 0;
    std::uint64_t lines_cast = 0;
    std::uint64_t oracle_nanoseconds = 0;  // spent computing line-based factors, all threads

    RefinementCounters& operator+=(const RefinementCounters& o) {
        oracle_calls += o.oracle_calls;
        oracle_evaluations += o.oracle_evaluations;
        cache_hits += o.cache_hits;
        lines_cast += o.lines_cast;
        oracle_nanoseconds += o.oracle_nanoseconds;
        return *this;
    }
};

// A side of a patch in one word: 2 * patch + side.
struct SideRef {
    std::uint32_t value = 0;

    SideRef() = default;
    SideRef(std::uint32_t patch, std::uint8_t side) : value(2 * patch + side) {}
    std::uint32_t patch() const { return value >> 1; }
    std::uint8_t side() const { return std::uint8_t(value & 1); }
};

// One ray's descent: its sides and points (24 bytes: a batch's descents read them at every
// level).
struct LinkQuery {
    SideRef receiver, source;
    Vec2f y_uv{0, 0}, x_uv{0, 0};  // the hit point on the receiver, the origin on the source
};

// Descends from (root of the receiver side, root of the source side), subdividing the larger
// element of a refused link towards the hit point y (receiver) or the ray origin x (source). One
// ray at a time from the roots, as docs/design.md §3 states it: the reference refine_links is
// tested against. For a refining mesh only, as refine_links (std::logic_error on a fixed one).
Element& refine_link(const RefinementContext& ctx, const LinkQuery& query,
                     RefinementCounters& counters);

// On a fixed mesh (ctx.fixed_leaves) the receiver is the mesh's leaf at the hit: the cluster
// leaf holding the side hit, or the side's leaf containing the hit point. It decides nothing and
// reads no element's power, so a frozen pass calls it as each ray is traced.
Element& fixed_receiver(const RefinementContext& ctx, const LinkQuery& query);

// refine_links' buffers, kept by the caller between calls.
struct DescentScratch {
    std::vector<Keyed<std::uint32_t>> keyed, keyed_scratch;
    std::vector<LinkQuery> grouped;
    std::vector<Element*> receivers;  // of the grouped queries
    std::vector<std::uint32_t> index, scratch;
    std::vector<std::uint8_t> child;       // of each index entry, at one level
    std::vector<std::size_t> group_start;  // where each (receiver, source) group begins

    // Room for `queries` at once: the rays that land vary from batch to batch, and buffers
    // sized to each batch would be moved to a larger block whenever one landed more.
    void reserve(std::size_t queries);
};

// The same descent for many rays at once, each ending on the element refine_link would give
// it (receivers[k] for queries[k]). Rays of one (receiver patch, source patch) pair share the
// upper levels of their descents, so each link on their shared paths is decided once for all
// of them, and the rays split between a refused link's children as their points do. Parallel;
// oracle_calls counts every ray's decisions, as refine_link does, so it does not depend on how
// rays are grouped. For a refining mesh only (std::logic_error on a fixed one).
void refine_links(const RefinementContext& ctx, std::span<const LinkQuery> queries,
                  std::span<Element*> receivers, RefinementCounters& counters,
                  DescentScratch& buffers);

}  // namespace hmcr
