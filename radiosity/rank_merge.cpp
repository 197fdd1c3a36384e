#include "radiosity/rank_merge.h"

#include <cstring>
#include <string>
#include <vector>

namespace hmcr {
namespace {

// An element id on the wire: patch, depth, path (13 bytes, no padding).
constexpr std::size_t kIdBytes = sizeof(std::uint32_t) + 1 + sizeof(std::uint64_t);

void put(std::string& out, const ElementId& id) {
    char b[kIdBytes];
    std::memcpy(b, &id.patch, 4);
    b[4] = char(id.depth);
    std::memcpy(b + 5, &id.path, 8);
    out.append(b, kIdBytes);
}

ElementId get(const char* b) {
    ElementId id;
    std::memcpy(&id.patch, b, 4);
    id.depth = std::uint8_t(b[4]);
    std::memcpy(&id.path, b + 5, 8);
    return id;
}

// The ids of every subdivided element, parents first.
std::string subdivided_ids(const Hierarchy& h) {
    std::string out;
    h.for_each_element([&](const Element& e) {
        if (!e.is_leaf()) put(out, e.id);
    });
    return out;
}

// Subdivides the element `id` names, and its ancestors first if they are not yet.
void subdivide_by_id(Hierarchy& h, const ElementId& id) {
    if (id.patch >= h.patch_count()) throw std::runtime_error("MPI: an element id out of range");
    Element* e = &h.root(id.patch);
    for (int level = id.depth - 1; level >= 0; --level) {
        e = h.subdivide(*e) + ((id.path >> (2 * level)) & 3);
    }
    h.subdivide(*e);
}

}  // namespace

RaySlice slice_of(std::uint64_t rays, int rank, int ranks) {
    const std::uint64_t k = std::uint64_t(ranks), q = rays / k, m = rays % k;
    const auto bound = [&](int r) { return q * std::uint64_t(r) + m * std::uint64_t(r) / k; };
    return {bound(rank), bound(rank + 1)};
}

void merge_iteration(Hierarchy& h, IterationOutcome& out, const Ranks& ranks, bool refined) {
    if (ranks.size() == 1) return;
    if (refined) {
        const std::vector<std::string> all = ranks.gather_all(subdivided_ids(h));
        together(ranks, [&] {
            for (int r = 0; r < ranks.size(); ++r) {
                if (r == ranks.rank()) continue;
                const std::string& ids = all[std::size_t(r)];
                for (std::size_t k = 0; k + kIdBytes <= ids.size(); k += kIdBytes) {
                    subdivide_by_id(h, get(ids.data() + k));
                }
            }
        });
    }
    // Every element's deposits, in the canonical order every rank now shares.
    std::vector<std::int64_t> quanta;
    quanta.reserve(3 * h.element_count() + 9);
    h.for_each_element([&](const Element& e) {
        quanta.insert(quanta.end(), e.received.begin(), e.received.end());
    });
    for (const Quanta* q : {&out.shot_power, &out.escaped_power, &out.back_face_power}) {
        quanta.insert(quanta.end(), q->begin(), q->end());
    }
    ranks.sum(quanta);
    std::size_t k = 0;
    h.for_each_element([&](Element& e) {
        for (auto& c : e.received) c = quanta[k++];
    });
    for (Quanta* q : {&out.shot_power, &out.escaped_power, &out.back_face_power}) {
        for (auto& c : *q) c = quanta[k++];
    }
    RefinementCounters& n = out.counters;
    std::vector<std::uint64_t> counts = {out.rays,           n.oracle_calls, n.oracle_evaluations,
                                         n.cache_hits,       n.lines_cast,   n.oracle_nanoseconds};
    ranks.sum(counts);
    out.rays = counts[0];
    n = {counts[1], counts[2], counts[3], counts[4], counts[5]};
}

}  // namespace hmcr
