// SPDX-License-Identifier: Apache-2.0
#include "radiosity/refinement.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/populated.h"
#include "radiosity/link_value.h"

namespace hmcr {

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
