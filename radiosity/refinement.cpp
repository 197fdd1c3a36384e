#include "radiosity/refinement.h"

#include <array>
#include <chrono>
#include <vector>

#include "radiosity/kernel.h"
#include "radiosity/rng.h"

namespace hmcr {
namespace {

// w_ij of SPEC section 4: the largest share of the source's radiosity the receiver reflects.
// The papers write it with the total radiosity B_j, as RenderPark's power oracle weighs; hmcr's
// first choice was the unshot Delta B_j, which refines later iterations much less.
double link_weight(const RefinementContext& ctx, const Element& receiver, const Element& source) {
    const Rgb& b = ctx.total_weight ? source.radiosity : source.unshot;
    return (ctx.hierarchy.patch(receiver).reflectance * b).maxCoeff();
}

std::uint64_t element_key(const ElementId& id) {
    return Rng(id.patch, id.path, id.depth).next_u64();
}

LinkGeometry centre_geometry(const Hierarchy& h, const Element& i, const Element& j) {
    LinkGeometry g;
    g.receiver_area = i.area;
    g.source_area = j.area;
    g.total_area = h.patch_set().total_area;
    const Vec3 d = j.centre - i.centre;
    g.centre_distance = d.norm();
    if (g.centre_distance > 0) {
        g.receiver_cos = std::max(0.0, h.patch(i).normal.dot(d) / g.centre_distance);
        g.source_cos = std::max(0.0, -h.patch(j).normal.dot(d) / g.centre_distance);
    }
    return g;
}

// The oracle's geometric factor from the pair's own N_s lines (SPEC sections 3 and 4).
double line_factor(const RefinementContext& ctx, const Element& receiver, const Element& source,
                   RefinementCounters& counters) {
    const auto start = std::chrono::steady_clock::now();
    thread_local std::vector<double> kernel;
    kernel.resize(std::size_t(ctx.lines));
    Rng rng(ctx.seed, element_key(receiver.id), element_key(source.id));
    sample_kernel(ctx.scene, ctx.hierarchy, receiver, source, rng, kernel);
    LinkGeometry g = centre_geometry(ctx.hierarchy, receiver, source);
    g.kernel = kernel;
    const double factor = ctx.oracle.geometric_factor(g);
    counters.lines_cast += kernel.size();
    ++counters.oracle_evaluations;
    counters.oracle_nanoseconds += std::uint64_t(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() -
                                                             start)
            .count());
    return factor;
}

double geometric_factor(const RefinementContext& ctx, const Element& receiver,
                        const Element& source, RefinementCounters& counters) {
    if (!ctx.oracle.uses_lines()) {
        ++counters.oracle_evaluations;
        return ctx.oracle.geometric_factor(centre_geometry(ctx.hierarchy, receiver, source));
    }
    if (!ctx.cache) return line_factor(ctx, receiver, source, counters);
    if (const auto cached = ctx.cache->find(&receiver, &source)) {
        ++counters.cache_hits;
        return *cached;
    }
    const double factor = line_factor(ctx, receiver, source, counters);
    ctx.cache->insert(&receiver, &source, factor);
    return factor;
}

}  // namespace

double link_value(const RefinementContext& ctx, const Element& receiver, const Element& source,
                  RefinementCounters& counters) {
    const double w = link_weight(ctx, receiver, source);
    if (w <= 0) return 0;  // nothing to transport: no refinement can matter
    ++counters.oracle_calls;
    return w * geometric_factor(ctx, receiver, source, counters);
}

Element& refine_link(const RefinementContext& ctx, std::uint32_t receiver_patch, const Vec2& y_uv,
                     std::uint32_t source_patch, const Vec2& x_uv, RefinementCounters& counters) {
    Hierarchy& h = ctx.hierarchy;
    Element* i = &h.root(receiver_patch);
    if (ctx.fixed_mesh) return h.locate(*i, y_uv);
    Element* j = &h.root(source_patch);
    for (;;) {
        const bool split_i = h.can_subdivide(*i), split_j = h.can_subdivide(*j);
        if (!split_i && !split_j) return *i;  // both at the limits: accept
        if (link_value(ctx, *i, *j, counters) < ctx.threshold) return *i;
        // Refused: the larger element that may still be split is replaced by its child holding
        // the ray's point on it (the hit point y on the receiver, the origin x on the source).
        Element*& e = split_i && (!split_j || i->area >= j->area) ? i : j;
        h.subdivide(*e);
        e = &h.child_containing(*e, &e == &i ? y_uv : x_uv);
    }
}

}  // namespace hmcr
