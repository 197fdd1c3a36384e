// SPDX-License-Identifier: Apache-2.0
#include "radiosity/link_value.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "radiosity/line_sampler.h"
#include "rays/rng.h"

namespace hmcr {
namespace {

// w_ij of docs/design.md §4: the largest share of the source's radiosity the receiver reflects.
// The papers write it with the total radiosity B_j, as RenderPark's power oracle weighs; hmcr's
// default is the unshot Delta B_j, which refines later iterations much less (§4.4).
double link_weight(const RefinementContext& ctx, const PatchPair& pp, const Element& source) {
    const Rgb& b = ctx.link_weight == LinkWeight::total ? source.radiosity : source.unshot;
    return (pp.reflectance * b).maxCoeff();
}

// A back side's elements draw from other streams than its front's.
std::uint64_t element_key(const ElementId& id) {
    return Rng(id.patch, id.path, id.depth + 256 * std::uint64_t(id.side)).next_u64();
}

// The cosine at element e's end of the centre line, along d of length `distance` (negating d
// is exact): 0 where the side faces away; at a cluster's end, which has no normal, its tree's
// (docs/design.md §2.7).
double end_cosine(const ClusterTree* clusters, const Element& e, const Vec3& normal, const Vec3& d,
                  double distance) {
    if (is_cluster(e)) return clusters->end_cosine(e, d / distance);
    return std::max(0.0, normal.dot(d) / distance);
}

LinkGeometry centre_geometry(const RefinementContext& ctx, const PatchPair& pp, const Element& i,
                             const Element& j) {
    LinkGeometry g;
    g.receiver_area = i.area;
    g.source_area = j.area;
    g.total_area = ctx.hierarchy.patch_set().total_area;
    const Vec3 d = j.centre - i.centre;
    g.centre_distance = d.norm();
    if (g.centre_distance > 0) {
        g.receiver_cos = end_cosine(ctx.clusters, i, pp.receiver_normal, d, g.centre_distance);
        g.source_cos = end_cosine(ctx.clusters, j, pp.source_normal, -d, g.centre_distance);
    }
    return g;
}

// A link with a cluster at an end none of whose lines carries light: a ray did, so the lines
// are too few to say how the light spreads over the cluster, whose sides may face away from
// it. Refused, so that the cluster is split (docs/design.md §2.7).
bool unseen_cluster_link(const Element& receiver, const Element& source,
                         std::span<const double> kernel) {
    return (is_cluster(receiver) || is_cluster(source)) &&
           std::all_of(kernel.begin(), kernel.end(), [](double f) { return f == 0; });
}

// The oracle's geometric factor from the pair's own N_s lines (docs/design.md §3, §4).
double line_factor(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                   const Element& source, RefinementCounters& counters) {
    const auto start = std::chrono::steady_clock::now();
    thread_local std::vector<double> kernel;
    kernel.resize(std::size_t(ctx.lines));
    Rng rng(ctx.seed, element_key(receiver.id), element_key(source.id));
    sample_kernel(ctx.scene, ctx.hierarchy, receiver, source, rng, kernel, ctx.clusters);
    LinkGeometry g = centre_geometry(ctx, pp, receiver, source);
    g.kernel = kernel;
    const double factor = unseen_cluster_link(receiver, source, kernel)
                              ? std::numeric_limits<double>::infinity()
                              : ctx.oracle.geometric_factor(g);
    counters.lines_cast += kernel.size();
    ++counters.oracle_evaluations;
    counters.oracle_nanoseconds +=
        std::uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                          std::chrono::steady_clock::now() - start)
                          .count());
    return factor;
}

// The factor from the centre line alone, for an oracle without lines.
double centre_factor(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                     const Element& source, RefinementCounters& counters) {
    ++counters.oracle_evaluations;
    return ctx.oracle.geometric_factor(centre_geometry(ctx, pp, receiver, source));
}

double geometric_factor(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                        const Element& source, RefinementCounters& counters) {
    const bool lines = ctx.oracle.uses_lines();
    // A receiver cluster's link to the top, found once an iteration (an oriented cluster's
    // cosines take a pass over its classes and the top's).
    if (is_cluster(receiver) && &source == &ctx.clusters->top()) {
        const double kept = ctx.clusters->top_factor(receiver);
        if (!std::isnan(kept)) return kept;
        const double factor = lines ? line_factor(ctx, pp, receiver, source, counters)
                                    : centre_factor(ctx, pp, receiver, source, counters);
        ctx.clusters->set_top_factor(receiver, factor);
        return factor;
    }
    if (!lines) return centre_factor(ctx, pp, receiver, source, counters);
    if (!ctx.cache) return line_factor(ctx, pp, receiver, source, counters);
    if (const auto cached = ctx.cache->find(&receiver, &source)) {
        ++counters.cache_hits;
        return *cached;
    }
    const double factor = line_factor(ctx, pp, receiver, source, counters);
    ctx.cache->insert(&receiver, &source, factor);
    return factor;
}

}  // namespace

PatchPair patch_pair(const RefinementContext& ctx, SideRef receiver, SideRef source) {
    const PatchSet& ps = ctx.hierarchy.patch_set();
    return {side_normal(ps.patches[receiver.patch()], receiver.side()),
            side_normal(ps.patches[source.patch()], source.side()),
            ctx.receiver_weights.empty()
                ? ps.material(receiver.patch(), receiver.side()).reflectance
                : ctx.receiver_weights[receiver.value]};
}

double link_value(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                  const Element& source, RefinementCounters& counters, std::uint64_t rays) {
    const double w = link_weight(ctx, pp, source);
    if (w <= 0) return 0;  // nothing to transport: no refinement can matter
    counters.oracle_calls += rays;
    return w * geometric_factor(ctx, pp, receiver, source, counters);
}

}  // namespace hmcr
