// Per-ray hierarchical refinement (SPEC section 3, step 5): the descent from the root link to
// the receiver element that takes the ray's power.
#pragma once

#include <cstdint>

#include "oracles/oracle.h"
#include "radiosity/embree_scene.h"
#include "radiosity/hierarchy.h"
#include "radiosity/link_cache.h"

namespace hmcr {

struct RefinementContext {
    Hierarchy& hierarchy;
    const Oracle& oracle;
    const EmbreeScene& scene;
    double threshold = 0;  // epsilon * Phi_max: a link is accepted when its value is below
    int lines = 10;        // N_s
    std::uint64_t seed = 0;
    LinkCache* cache = nullptr;  // geometric factors of line-based oracles; none: recompute
    bool fixed_mesh = false;     // deposit on the existing leaf at the hit, ask no oracle
    bool total_weight = false;   // w_ij from the source's B (RenderPark's), else its Delta B
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

// Descends from (root of receiver_patch, root of source_patch), subdividing the larger element
// of a refused link towards the hit point y (receiver) or the ray origin x (source).
Element& refine_link(const RefinementContext& ctx, std::uint32_t receiver_patch, const Vec2& y_uv,
                     std::uint32_t source_patch, const Vec2& x_uv, RefinementCounters& counters);

// The oracle's value of a link divided by Phi_max is compared with epsilon; this is the value.
double link_value(const RefinementContext& ctx, const Element& receiver, const Element& source,
                  RefinementCounters& counters);

}  // namespace hmcr
