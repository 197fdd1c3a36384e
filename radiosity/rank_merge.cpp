// SPDX-License-Identifier: Apache-2.0
#include "radiosity/rank_merge.h"

#include <algorithm>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "rays/embree_scene.h"

namespace hmcr {
namespace {

// An element on the wire: patch, depth, side, path and whether it is split (14 bytes, no
// padding). A side's root that exists unsplit is sent too: a back side's root is made where light
// first reaches it, which may be on one rank only.
constexpr std::size_t kIdBytes = sizeof(std::uint32_t) + 2 + sizeof(std::uint64_t);

void put(std::string& out, const ElementId& id, bool split) {
    char b[kIdBytes];
    std::memcpy(b, &id.patch, 4);
    b[4] = char(id.depth);
    b[5] = char(id.side | (split ? 2 : 0));
    std::memcpy(b + 6, &id.path, 8);
    out.append(b, kIdBytes);
}

struct WireElement {
    ElementId id;
    bool split = false;
};

WireElement get(const char* b) {
    WireElement w;
    std::memcpy(&w.id.patch, b, 4);
    w.id.depth = std::uint8_t(b[4]);
    w.id.side = std::uint8_t(b[5] & 1);
    w.split = (b[5] & 2) != 0;
    std::memcpy(&w.id.path, b + 6, 8);
    return w;
}

// The ids of every split element, parents first, and of the back roots that are leaves.
std::string element_ids(const Hierarchy& h) {
    std::string out;
    h.for_each_element([&](const Element& e) {
        if (!e.is_leaf()) {
            put(out, e.id, true);
        } else if (e.id.side == kBack && e.id.depth == 0) {
            put(out, e.id, false);
        }
    });
    return out;
}

// Makes the element `w` names, and its ancestors first, and splits it if it is split.
void make_by_id(Hierarchy& h, const WireElement& w) {
    const ElementId& id = w.id;
    if (id.patch >= h.patch_count() || (id.side == kBack && !h.patch_set().two_sided(id.patch))) {
        throw std::runtime_error("MPI: an element id out of range");
    }
    Element* e = &h.root(id.patch, id.side);
    for (int level = id.depth - 1; level >= 0; --level) {
        e = h.subdivide(*e) + ((id.path >> (2 * level)) & 3);
    }
    if (w.split) h.subdivide(*e);
}

}  // namespace

RaySlice slice_of(std::uint64_t rays, int rank, int ranks) {
    // Whole packets, so that every rank traces the packets one rank would (rays/embree_scene.h).
    constexpr std::uint64_t kPacket = EmbreeScene::kPacketRays;
    const std::uint64_t packets = rays / kPacket + (rays % kPacket != 0);
    const std::uint64_t k = std::uint64_t(ranks), q = packets / k, m = packets % k;
    const auto bound = [&](int r) {
        return std::min(rays, kPacket * (q * std::uint64_t(r) + m * std::uint64_t(r) / k));
    };
    return {bound(rank), bound(rank + 1)};
}

void merge_iteration(Hierarchy& h, IterationOutcome& out, const Ranks& ranks, bool refined,
                     ClusterTree* clusters) {
    if (ranks.size() == 1) return;
    // Backs may appear on a fixed mesh too, where a ray first reaches one.
    if (refined || !h.patch_set().back_materials.empty()) {
        const std::vector<std::string> all = ranks.gather_all(element_ids(h));
        together(ranks, [&] {
            for (int r = 0; r < ranks.size(); ++r) {
                if (r == ranks.rank()) continue;
                const std::string& ids = all[std::size_t(r)];
                for (std::size_t k = 0; k + kIdBytes <= ids.size(); k += kIdBytes) {
                    make_by_id(h, get(ids.data() + k));
                }
            }
        });
    }
    // Every element's deposits, in the canonical order every rank now shares, and the clusters'
    // open flags (a cluster is open if it is on any rank: the sum is not 0).
    std::vector<std::int64_t> quanta;
    quanta.reserve(3 * h.element_count() + 9);
    h.for_each_element([&](const Element& e) {
        quanta.insert(quanta.end(), e.received.begin(), e.received.end());
    });
    // A higher basis's deposits toward the coefficients beyond the mean, element by element.
    const int terms = basis_size(h.basis()) - 1;
    const auto each_term = [&](auto&& f) {
        if (terms == 0) return;
        h.for_each_element([&](const Element& e) {
            TermSlot* t = h.terms(e);
            for (int j = 0; j < terms; ++j) f(t[j].received);
        });
    };
    each_term([&](const Quanta& q) { quanta.insert(quanta.end(), q.begin(), q.end()); });
    const auto each_cluster = [&](auto&& f) {
        if (clusters) clusters->for_each_cluster(f);
    };
    each_cluster([&](const Element& e) {
        quanta.insert(quanta.end(), e.received.begin(), e.received.end());
    });
    const std::span<Quanta> classes = clusters ? clusters->class_received() : std::span<Quanta>{};
    for (const Quanta& q : classes) quanta.insert(quanta.end(), q.begin(), q.end());
    for (const Quanta* q : {&out.shot_power, &out.escaped_power, &out.back_face_power}) {
        quanta.insert(quanta.end(), q->begin(), q->end());
    }
    const bool opens = refined && clusters;
    if (opens) {
        const std::vector<std::int64_t> open = clusters->open_flags();
        quanta.insert(quanta.end(), open.begin(), open.end());
    }
    ranks.sum(quanta);
    std::size_t k = 0;
    const auto take = [&](Element& e) {
        for (auto& c : e.received) c = quanta[k++];
    };
    h.for_each_element(take);
    each_term([&](Quanta& q) {
        for (auto& c : q) c = quanta[k++];
    });
    each_cluster(take);
    for (Quanta& q : classes) {
        for (auto& c : q) c = quanta[k++];
    }
    for (Quanta* q : {&out.shot_power, &out.escaped_power, &out.back_face_power}) {
        for (auto& c : *q) c = quanta[k++];
    }
    if (opens) clusters->set_open_flags(std::span<const std::int64_t>(quanta).subspan(k));
    RefinementCounters& n = out.counters;
    std::vector<std::uint64_t> counts = {out.rays,     n.oracle_calls, n.oracle_evaluations,
                                         n.cache_hits, n.lines_cast,   n.oracle_nanoseconds};
    ranks.sum(counts);
    out.rays = counts[0];
    n = {counts[1], counts[2], counts[3], counts[4], counts[5]};
}

}  // namespace hmcr
