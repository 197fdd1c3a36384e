#include "radiosity/refinement.h"

#include <array>
#include <vector>

#include "radiosity/kernel.h"
#include "radiosity/rng.h"

namespace hmcr {
namespace {

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

}  // namespace

double link_value(const RefinementContext& ctx, const Element& receiver, const Element& source,
                  RefinementCounters& counters) {
    const Hierarchy& h = ctx.hierarchy;
    const double w = link_weight(h.patch(receiver).reflectance, source.unshot);
    if (w <= 0) return 0;
    ++counters.oracle_calls;
    LinkGeometry g = centre_geometry(h, receiver, source);
    std::vector<double> kernel;
    if (ctx.oracle.uses_lines()) {
        // The pair's own stream: the same lines whichever ray asks (SPEC section 3).
        Rng rng(ctx.seed, element_key(receiver.id), element_key(source.id));
        kernel.resize(std::size_t(ctx.lines));
        sample_kernel(ctx.scene, h, receiver, source, rng, kernel);
        counters.lines_cast += kernel.size();
        g.kernel = kernel;
    }
    return w * ctx.oracle.geometric_factor(g);
}

Element& refine_link(const RefinementContext& ctx, std::uint32_t receiver_patch, const Vec2& y_uv,
                     std::uint32_t source_patch, const Vec2& x_uv, RefinementCounters& counters) {
    Hierarchy& h = ctx.hierarchy;
    Element* i = &h.root(receiver_patch);
    Element* j = &h.root(source_patch);
    for (;;) {
        const bool split_i = h.can_subdivide(*i), split_j = h.can_subdivide(*j);
        if (!split_i && !split_j) return *i;  // both at the limits: accept
        if (link_value(ctx, *i, *j, counters) < ctx.threshold) return *i;
        // Subdivide the larger element of the pair (or the one that still can be).
        if (split_i && (!split_j || i->area >= j->area)) {
            h.subdivide(*i);
            i = &h.child_containing(*i, y_uv);
        } else {
            h.subdivide(*j);
            j = &h.child_containing(*j, x_uv);
        }
    }
}

}  // namespace hmcr
