// SPDX-License-Identifier: Apache-2.0
#include "radiosity/refinement.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/populated.h"
#include "radiosity/line_sampler.h"
#include "rays/rng.h"

namespace hmcr {
namespace {

// What every link between two patches shares: their normals and the receiver's reflectance
// (or its importance-weighted stand-in), read once for a descent (or a group of them) rather
// than once for each link decided.
struct PatchPair {
    Vec3 receiver_normal, source_normal;
    Rgb reflectance;  // the receiver's
};

PatchPair patch_pair(const RefinementContext& ctx, SideRef receiver, SideRef source) {
    const PatchSet& ps = ctx.hierarchy.patch_set();
    return {side_normal(ps.patches[receiver.patch()], receiver.side()),
            side_normal(ps.patches[source.patch()], source.side()),
            ctx.receiver_weights.empty()
                ? ps.material(receiver.patch(), receiver.side()).reflectance
                : ctx.receiver_weights[receiver.value]};
}

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

// The cosine at one end of the centre line, along d of length `distance` (negating d is exact):
// 0 where the side faces away; 1/4 at a cluster's end, which has no normal (docs/design.md §2.7).
double end_cosine(const Vec3& normal, const Vec3& d, double distance) {
    if (normal == Vec3::Zero()) return 0.25;
    return std::max(0.0, normal.dot(d) / distance);
}

LinkGeometry centre_geometry(const Hierarchy& h, const PatchPair& pp, const Element& i,
                             const Element& j) {
    LinkGeometry g;
    g.receiver_area = i.area;
    g.source_area = j.area;
    g.total_area = h.patch_set().total_area;
    const Vec3 d = j.centre - i.centre;
    g.centre_distance = d.norm();
    if (g.centre_distance > 0) {
        g.receiver_cos = end_cosine(pp.receiver_normal, d, g.centre_distance);
        g.source_cos = end_cosine(pp.source_normal, -d, g.centre_distance);
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
    LinkGeometry g = centre_geometry(ctx.hierarchy, pp, receiver, source);
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

double geometric_factor(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                        const Element& source, RefinementCounters& counters) {
    if (!ctx.oracle.uses_lines()) {
        ++counters.oracle_evaluations;
        return ctx.oracle.geometric_factor(centre_geometry(ctx.hierarchy, pp, receiver, source));
    }
    if (is_cluster(receiver) && &source == &ctx.clusters->top()) {
        const double kept = ctx.clusters->top_factor(receiver);
        if (!std::isnan(kept)) return kept;
        const double factor = line_factor(ctx, pp, receiver, source, counters);
        ctx.clusters->set_top_factor(receiver, factor);
        return factor;
    }
    if (!ctx.cache) return line_factor(ctx, pp, receiver, source, counters);
    if (const auto cached = ctx.cache->find(&receiver, &source)) {
        ++counters.cache_hits;
        return *cached;
    }
    const double factor = line_factor(ctx, pp, receiver, source, counters);
    ctx.cache->insert(&receiver, &source, factor);
    return factor;
}

// The oracle's value of a link: w_ij times its geometric factor, to be compared with
// epsilon * Phi_max. Counted as `rays` decisions (oracle_calls) when the link carries anything.
double link_value(const RefinementContext& ctx, const PatchPair& pp, const Element& receiver,
                  const Element& source, RefinementCounters& counters, std::uint64_t rays) {
    const double w = link_weight(ctx, pp, source);
    if (w <= 0) return 0;  // nothing to transport: no refinement can matter
    counters.oracle_calls += rays;
    return w * geometric_factor(ctx, pp, receiver, source, counters);
}

}  // namespace

namespace {

// One step of the descent at the link (i, j), for both descents below: accepted (both at the
// limits, or the oracle's value below the threshold), or which element to split if refused:
// the larger one that may still be split. Counted as `rays` decisions.
enum class Step { accept, split_receiver, split_source };

// A cluster may always be split, into its children; an element within the limits of §2.5.
bool splittable(const RefinementContext& ctx, const Element& e) {
    return is_cluster(e) || ctx.hierarchy.can_subdivide(e);
}

// The pair of a link with a cluster at an end (docs/design.md §2.7): that end has no normal
// (isotropic), and a cluster receiver's weight is the area-weighted mean of its sides'.
PatchPair cluster_pair(const RefinementContext& ctx, PatchPair pp, const Element& i,
                       const Element& j) {
    if (is_cluster(i)) {
        pp.receiver_normal = Vec3::Zero();
        pp.reflectance = ctx.clusters->receiver_weight(i);
    }
    if (is_cluster(j)) pp.source_normal = Vec3::Zero();
    return pp;
}

Step next_step(const RefinementContext& ctx, const PatchPair& pp, const Element& i,
               const Element& j, RefinementCounters& counters, std::uint64_t rays) {
    const bool split_i = splittable(ctx, i), split_j = splittable(ctx, j);
    if (!split_i && !split_j) return Step::accept;
    // The cluster joining fronts and backs never receives: it holds the two sides of a patch,
    // which face apart (docs/design.md §2.7).
    if (is_cluster(i) && !ctx.clusters->may_receive(i)) return Step::split_receiver;
    const double value = is_cluster(i) || is_cluster(j)
                             ? link_value(ctx, cluster_pair(ctx, pp, i, j), i, j, counters, rays)
                             : link_value(ctx, pp, i, j, counters, rays);
    if (value < ctx.threshold) return Step::accept;
    // A receiver cluster is split before its source, the top cluster: its decision is the same
    // for every source, which keeps the furnace exact. Once the receiver is a side's root the
    // source is its side's root (docs/design.md §2.7).
    return is_cluster(i) || (split_i && (!split_j || i.area >= j.area)) ? Step::split_receiver
                                                                        : Step::split_source;
}

// A refused receiver cluster is split (and so opened, a part of the mesh no more): the receiver
// becomes its child holding the ray's side, and once that is a side's root the source becomes
// its own side's root (docs/design.md §2.7).
void split_cluster(const RefinementContext& ctx, Element*& i, Element*& j, const LinkQuery& q) {
    ctx.clusters->open(*i);
    i = &ctx.clusters->child_toward(*i, q.receiver.value);
    if (!is_cluster(*i)) j = &ctx.hierarchy.root(q.source.patch(), q.source.side());
}

// The descents refine a mesh; a fixed mesh's receivers are fixed_receiver's.
void require_refining(const RefinementContext& ctx, const char* caller) {
    if (ctx.fixed_leaves) {
        throw std::logic_error(std::string(caller) +
                               " on a fixed mesh: its receivers are "
                               "fixed_receiver's");
    }
}

}  // namespace

Element& fixed_receiver(const RefinementContext& ctx, const LinkQuery& q) {
    if (ctx.clusters) {
        if (Element* c = ctx.clusters->closed_leaf(q.receiver.value)) return *c;
    }
    return ctx.fixed_leaves->locate(q.receiver.patch(), q.receiver.side(), q.y_uv.cast<double>());
}

Element& refine_link(const RefinementContext& ctx, const LinkQuery& query,
                     RefinementCounters& counters) {
    require_refining(ctx, "refine_link");
    Hierarchy& h = ctx.hierarchy;
    const Vec2 y_uv = query.y_uv.cast<double>(), x_uv = query.x_uv.cast<double>();
    Element* i = &h.root(query.receiver.patch(), query.receiver.side());
    Element* j = &h.root(query.source.patch(), query.source.side());
    if (ctx.clusters) i = j = &ctx.clusters->top();
    const PatchPair pp = patch_pair(ctx, query.receiver, query.source);
    for (;;) {
        const Step step = next_step(ctx, pp, *i, *j, counters, 1);
        if (step == Step::accept) return *i;
        // Refused: the element split is replaced by its child holding the ray's point on it
        // (the hit point y on the receiver, the origin x on the source), a cluster by its child
        // holding the ray's side.
        Element*& e = step == Step::split_receiver ? i : j;
        if (is_cluster(*e)) {
            split_cluster(ctx, i, j, query);
            continue;
        }
        if (ctx.clusters && &e == &j) ctx.clusters->open_above(query.source.value);
        h.subdivide(*e);
        e = &h.child_containing(*e, &e == &i ? y_uv : x_uv);
    }
}

namespace {

// A group this large splits its children's descents between threads.
constexpr std::size_t kParallelRays = 2048;
// How many groups ahead refine_links loads a group's first link from the link cache.
constexpr std::size_t kAhead = 4;

// What every descent of one (receiver patch, source patch) group shares: the grouped queries,
// where each one's receiver goes, and the pair's patch data.
struct Descent {
    const LinkQuery* rays;
    Element** receivers;
    PatchPair patches;
};

// refine_link's loop for the rays rays[index[0..n)], which all reach the link (i, j). A refused
// link's rays are scattered by child into `scratch` (the same range of a second buffer), which
// becomes the children's `index`; `child` holds each entry's child at the level being split.
void descend(const RefinementContext& ctx, const Descent& d, Element* i, Element* j,
             std::uint32_t* index, std::uint32_t* scratch, std::uint8_t* child, std::size_t n,
             RefinementCounters& counters) {
    Hierarchy& h = ctx.hierarchy;
    for (;;) {
        const Step step = next_step(ctx, d.patches, *i, *j, counters, n);
        if (step == Step::accept) break;
        const bool on_i = step == Step::split_receiver;
        Element*& e = on_i ? i : j;
        if (is_cluster(*e)) {  // every ray of the group holds the same sides
            split_cluster(ctx, i, j, d.rays[index[0]]);
            continue;
        }
        if (ctx.clusters && !on_i) ctx.clusters->open_above(d.rays[index[0]].source.value);
        Element* const children = h.subdivide(*e);
        // The children's links come next: their cache sets load while the rays are sorted among
        // the children (all four, whose counts are not known yet).
        if (ctx.cache) {
            for (std::size_t k = 0; k < 4; ++k) {
                ctx.cache->prefetch(on_i ? &children[k] : i, on_i ? j : &children[k]);
            }
        }
        const bool quad = h.patch(*e).is_quad();
        std::array<std::size_t, 4> count{};
        for (std::size_t t = 0; t < n; ++t) {
            const LinkQuery& q = d.rays[index[t]];
            const Vec2f& uv = on_i ? q.y_uv : q.x_uv;
            child[t] = std::uint8_t(e->domain.child_containing(quad, uv.cast<double>()));
            ++count[child[t]];
        }
        const int first = child[0];
        if (count[std::size_t(first)] == n) {  // all in one child: the loop goes on
            e = &children[first];
            continue;
        }
        std::array<std::size_t, 5> start{};
        for (std::size_t k = 0; k < 4; ++k) start[k + 1] = start[k] + count[k];
        std::array<std::size_t, 4> next{start[0], start[1], start[2], start[3]};
        for (std::size_t t = 0; t < n; ++t) scratch[next[child[t]]++] = index[t];
        auto child_descent = [&](std::size_t k, RefinementCounters& c) {
            if (count[k] == 0) return;
            Element* ck = &children[k];
            descend(ctx, d, on_i ? ck : i, on_i ? j : ck, scratch + start[k], index + start[k],
                    child + start[k], count[k], c);
        };
        if (n < kParallelRays) {
            for (std::size_t k = 0; k < 4; ++k) child_descent(k, counters);
            return;
        }
        std::array<RefinementCounters, 4> sub{};
        tbb::parallel_for(std::size_t(0), std::size_t(4),
                          [&](std::size_t k) { child_descent(k, sub[k]); });
        for (const RefinementCounters& c : sub) counters += c;
        return;
    }
    for (std::size_t t = 0; t < n; ++t) d.receivers[index[t]] = i;
}

}  // namespace

void DescentScratch::reserve(std::size_t queries) {
    reserve_populated(keyed, queries);
    reserve_populated(keyed_scratch, queries);
    reserve_populated(grouped, queries);
    reserve_populated(receivers, queries);
    reserve_populated(index, queries);
    reserve_populated(scratch, queries);
    reserve_populated(child, queries);
}

void refine_links(const RefinementContext& ctx, std::span<const LinkQuery> queries,
                  std::span<Element*> receivers, RefinementCounters& counters,
                  DescentScratch& buffers) {
    require_refining(ctx, "refine_links");
    Hierarchy& h = ctx.hierarchy;
    // Grouped by (receiver side, source side), each group's queries copied together so that
    // its descent reads a compact block.
    const std::uint64_t sides = 2 * std::uint64_t(h.patch_count());
    auto& keyed = buffers.keyed;
    resize_populated(keyed, queries.size());
    Keyed<std::uint32_t>* const keys = keyed.data();
    tbb::parallel_for(std::size_t(0), queries.size(), [&](std::size_t k) {
        keys[k] = {queries[k].receiver.value * sides + queries[k].source.value, std::uint32_t(k)};
    });
    radix_sort(keyed, buffers.keyed_scratch);  // swaps the two vectors: `keys` may be stale
    resize_populated(buffers.grouped, queries.size());
    resize_populated(buffers.receivers, queries.size());
    resize_populated(buffers.index, queries.size());
    resize_populated(buffers.scratch, queries.size());
    resize_populated(buffers.child, queries.size());
    LinkQuery* const grouped = buffers.grouped.data();
    std::uint32_t* const index = buffers.index.data();
    std::uint32_t* const scratch = buffers.scratch.data();
    std::uint8_t* const child = buffers.child.data();
    const Keyed<std::uint32_t>* const sorted = keyed.data();
    tbb::parallel_for(std::size_t(0), queries.size(), [&](std::size_t t) {
        grouped[t] = queries[sorted[t].value];
        index[t] = std::uint32_t(t);
    });
    auto& group_start = buffers.group_start;
    group_start.clear();
    for (std::size_t t = 0; t < keyed.size(); ++t) {
        if (t == 0 || keyed[t].key != keyed[t - 1].key) group_start.push_back(t);
    }
    group_start.push_back(keyed.size());
    // The link cache's set of a group's first link between patches, (receiver root, source
    // root), loaded a few groups before that link is decided (with clusters, after the cluster
    // links above it): with more patch pairs than a thread's front table holds, a batch's
    // groups are mostly pairs whose sets are far in memory.
    auto prefetch_group = [&](std::size_t g) {
        const LinkQuery& q = grouped[group_start[g]];
        const Element* i = h.made_root(q.receiver.patch(), q.receiver.side());
        const Element* j = h.made_root(q.source.patch(), q.source.side());
        if (i && j) ctx.cache->prefetch(i, j);
    };
    tbb::enumerable_thread_specific<RefinementCounters> local;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, group_start.size() - 1, 1), [&](auto r) {
        RefinementCounters& c = local.local();
        if (ctx.cache) {
            for (std::size_t g = r.begin(); g < std::min(r.end(), r.begin() + kAhead); ++g) {
                prefetch_group(g);
            }
        }
        for (std::size_t g = r.begin(); g < r.end(); ++g) {
            if (ctx.cache && g + kAhead < r.end()) prefetch_group(g + kAhead);
            const std::size_t first = group_start[g], n = group_start[g + 1] - first;
            const LinkQuery& q = grouped[first];
            const Descent d{grouped, buffers.receivers.data(),
                            patch_pair(ctx, q.receiver, q.source)};
            Element* const top = ctx.clusters ? &ctx.clusters->top() : nullptr;
            descend(ctx, d, top ? top : &h.root(q.receiver.patch(), q.receiver.side()),
                    top ? top : &h.root(q.source.patch(), q.source.side()), index + first,
                    scratch + first, child + first, n, c);
        }
    });
    for (const RefinementCounters& c : local) counters += c;
    Element* const* const grouped_receivers = buffers.receivers.data();
    tbb::parallel_for(std::size_t(0), queries.size(),
                      [&](std::size_t t) { receivers[sorted[t].value] = grouped_receivers[t]; });
}

}  // namespace hmcr
