// SPDX-License-Identifier: Apache-2.0
// Groups of faces on the same vertices, found by sorting (vertex set, index) records: at 10^6
// faces a hash map's node per face was a seventh of the load.
#include "meshes/coincident_faces.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <optional>
#include <span>

#include "common/error.h"
#include "meshes/validation.h"

namespace hmcr {
namespace {

// Why a face goes (or stays).
enum class Fate : std::uint8_t { kept, duplicate, joined, conflict };

// What makes two faces on the same vertices copies, whatever their corner count.
struct Sides {
    const PolygonSoup& soup;

    bool same_material(std::int32_t a, std::int32_t b) const {
        if (a == b) return true;
        if (a < 0 || b < 0) return false;
        const SoupMaterial& x = soup.materials[std::size_t(a)];
        const SoupMaterial& y = soup.materials[std::size_t(b)];
        return x.defined && y.defined && x.material.kd == y.material.kd &&
               x.material.ke == y.material.ke && x.material.ks == y.material.ks &&
               x.material.roughness == y.material.roughness;
    }
    // Faces a and b (soup indices) in the same material with the same back.
    bool same_sides(std::uint32_t a, std::uint32_t b) const {
        return same_material(soup.material[a], soup.material[b]) &&
               (soup.back[a] == soup.back[b] || same_material(soup.back[a], soup.back[b]));
    }
};

struct Record {
    FaceKey set;  // the sorted ids
    std::uint32_t index;
};

// Triangles and quads, each known by its Record.
struct Faces : Sides {
    std::vector<FaceKey> cyclic;  // per polygon: its ids from the smallest, in its order

    std::uint32_t index(const Record& r) const { return r.index; }
    // Same vertices in the same cyclic order: the same way; in the reversed order: opposite.
    // (Two faces on one set of 3 or 4 vertices that pass the patch checks are one polygon,
    // either way round; a strict load may hold others, which are neither.)
    bool same_way(const Record& a, const Record& b) const {
        return same_key(cyclic[a.index], cyclic[b.index]);
    }
    bool opposite(const Record& a, const Record& b) const {
        const FaceKey& k = cyclic[a.index];
        const bool quad = k[3] != std::numeric_limits<int>::max();
        const FaceKey reversed =
            quad ? FaceKey{k[0], k[3], k[2], k[1]} : FaceKey{k[0], k[2], k[1], k[3]};
        return same_key(reversed, cyclic[b.index]);
    }
    bool copy(const Record& a, const Record& b) const {
        return same_way(a, b) && same_sides(a.index, b.index);
    }
};

// The ids in the same cyclic order starting at the smallest, then INT_MAX: equal for the same
// face written from another corner, not for the reversed face.
FaceKey cyclic_key(const std::vector<int>& ids) {
    FaceKey key;
    key.fill(std::numeric_limits<int>::max());
    const std::size_t n = ids.size();
    const std::size_t first = std::size_t(std::min_element(ids.begin(), ids.end()) - ids.begin());
    for (std::size_t i = 0; i < n; ++i) key[i] = ids[(first + i) % n];
    return key;
}

// The records of the usable faces, sorted by vertex set and then file order; fills `faces`.
std::vector<Record> sorted_records(Faces& faces, const std::vector<int>& welded) {
    const PolygonSoup& soup = faces.soup;
    faces.cyclic.resize(soup.polygon_count());
    std::vector<Record> records;
    records.reserve(soup.polygon_count());
    std::vector<int> ids;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        ids.clear();
        for (std::uint32_t c : soup.corners(k)) ids.push_back(welded[c]);
        if (ids.size() < 3 || ids.size() > 4) continue;
        const FaceKey set = face_key(ids);
        if (std::adjacent_find(set.begin(), set.begin() + std::ptrdiff_t(ids.size())) !=
            set.begin() + std::ptrdiff_t(ids.size())) {
            continue;  // a repeated corner: not a face (strict loads only)
        }
        faces.cyclic[k] = cyclic_key(ids);
        records.push_back({set, std::uint32_t(k)});
    }
    std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
        return key_order(a.set, a.index, b.set, b.index);
    });
    return records;
}

// "on lines A and B" when both are in the file of `at`, else "at FILE:A and FILE:B".
std::string places_of(const PolygonSoup& soup, SourcePlace a, SourcePlace b, SourcePlace at) {
    if (a.file == at.file && b.file == at.file)
        return fmt::format("on {}s {} and {}", soup.item_word(a.file), a.line, b.line);
    return fmt::format("at {} and {}", soup.where(a), soup.where(b));
}

// A third face on the vertices of two kept ones, the earliest in file order.
struct Third {
    std::uint32_t face, first, second;
};

[[noreturn]] void refuse(const PolygonSoup& soup, const Third& t) {
    const SourcePlace at = soup.place[t.face];
    throw InputError(soup.where(at),
                     fmt::format("a third face on the same vertices as the faces {}: a surface "
                                 "has two sides",
                                 places_of(soup, soup.place[t.first], soup.place[t.second], at)));
}

// The fates of one group's faces (handles of one vertex set, in file order); a third face kept
// is returned, not thrown, so that the earliest of all groups is the one named.
template <class FaceSet, class Handle>
std::optional<Third> resolve_group(const FaceSet& faces, std::span<const Handle> group,
                                   PolygonSoup& soup, std::vector<Fate>& fate) {
    const Handle* kept[2];
    std::size_t n = 0;
    for (const Handle& h : group) {
        const std::uint32_t f = faces.index(h);
        if (std::any_of(kept, kept + n, [&](const Handle* k) { return faces.copy(*k, h); })) {
            fate[f] = Fate::duplicate;
        } else if (n == 2) {
            return Third{f, faces.index(*kept[0]), faces.index(*kept[1])};
        } else {
            kept[n++] = &h;
        }
    }
    if (n < 2) return std::nullopt;
    const std::uint32_t first = faces.index(*kept[0]), second = faces.index(*kept[1]);
    if (faces.opposite(*kept[0], *kept[1])) {
        soup.back[first] = soup.material[second];
        fate[second] = Fate::joined;
    } else {
        fate[second] = Fate::conflict;
    }
    return std::nullopt;
}

// Drops the faces whose fate is not `kept`, counting each at its place in file order.
void drop(PolygonSoup& soup, const std::vector<Fate>& fate, RepairReport& report) {
    constexpr RepairKind kKind[] = {RepairKind::duplicate_dropped, RepairKind::duplicate_dropped,
                                    RepairKind::sides_joined, RepairKind::coincident_dropped};
    PolygonSoup kept;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        if (fate[k] == Fate::kept) {
            kept.add_polygon(soup.corners(k), soup.material[k], soup.place[k], soup.back[k]);
        } else {
            report.add(kKind[std::size_t(fate[k])], soup.where(soup.place[k]));
        }
    }
    soup.corner_offsets = std::move(kept.corner_offsets);
    soup.corner_ids = std::move(kept.corner_ids);
    soup.material = std::move(kept.material);
    soup.back = std::move(kept.back);
    soup.place = std::move(kept.place);
}

// Calls group(span) for each run of two or more equal handles (same(a, b)) of the sorted list.
template <class Handle, class Same, class Group>
void for_each_group(const std::vector<Handle>& sorted, Same&& same, Group&& group) {
    for (std::size_t begin = 0, end = 1; begin < sorted.size(); begin = end++) {
        while (end < sorted.size() && same(sorted[end], sorted[begin])) ++end;
        if (end - begin >= 2) group(std::span<const Handle>(sorted.data() + begin, end - begin));
    }
}

bool same_record_set(const Record& a, const Record& b) { return same_key(a.set, b.set); }

// Faces of 5 corners or more, each known by its slot (in file order), with its welded ids flat:
// from its smallest id in its order, and sorted. A million pentagons are two arrays, not a
// million vectors.
struct Polygons : Sides {
    std::vector<std::uint32_t> face;    // per slot: its soup index
    std::vector<std::size_t> begin{0};  // per slot: its ids' offset (one more at the end)
    std::vector<int> cyclic, sorted;

    std::uint32_t index(std::uint32_t slot) const { return face[slot]; }
    std::span<const int> cyclic_of(std::uint32_t s) const {
        return {cyclic.data() + begin[s], begin[s + 1] - begin[s]};
    }
    std::span<const int> sorted_of(std::uint32_t s) const {
        return {sorted.data() + begin[s], begin[s + 1] - begin[s]};
    }
    bool same_set(std::uint32_t a, std::uint32_t b) const {
        return std::ranges::equal(sorted_of(a), sorted_of(b));
    }
    bool same_way(std::uint32_t a, std::uint32_t b) const {
        return std::ranges::equal(cyclic_of(a), cyclic_of(b));
    }
    // The same smallest id first, then the rest in reverse.
    bool opposite(std::uint32_t a, std::uint32_t b) const {
        const std::span<const int> x = cyclic_of(a), y = cyclic_of(b);
        const std::size_t n = x.size();
        if (y.size() != n || x[0] != y[0]) return false;
        for (std::size_t k = 1; k < n; ++k) {
            if (x[k] != y[n - k]) return false;
        }
        return true;
    }
    bool copy(std::uint32_t a, std::uint32_t b) const {
        return same_way(a, b) && same_sides(face[a], face[b]);
    }
    // Slots by corner count, then sorted ids, then file order.
    bool before(std::uint32_t a, std::uint32_t b) const {
        const std::span<const int> x = sorted_of(a), y = sorted_of(b);
        if (x.size() != y.size()) return x.size() < y.size();
        const auto [i, j] = std::mismatch(x.begin(), x.end(), y.begin());
        return i != x.end() ? *i < *j : a < b;
    }
};

// The faces of the soup with 5 distinct corners or more (a face with a seam, which repeats
// corners, is left as it is), in slots; returns the slots in the order of Polygons::before.
std::vector<std::uint32_t> sorted_polygons(Polygons& polygons, const std::vector<int>& welded) {
    const PolygonSoup& soup = polygons.soup;
    std::vector<int> ids, set;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        if (soup.corners(k).size() < 5) continue;
        ids.clear();
        for (std::uint32_t c : soup.corners(k)) ids.push_back(welded[c]);
        set = ids;
        std::sort(set.begin(), set.end());
        if (std::adjacent_find(set.begin(), set.end()) != set.end()) continue;
        const auto first = std::min_element(ids.begin(), ids.end());
        polygons.cyclic.insert(polygons.cyclic.end(), first, ids.end());
        polygons.cyclic.insert(polygons.cyclic.end(), ids.begin(), first);
        polygons.sorted.insert(polygons.sorted.end(), set.begin(), set.end());
        polygons.face.push_back(std::uint32_t(k));
        polygons.begin.push_back(polygons.cyclic.size());
    }
    std::vector<std::uint32_t> order(polygons.face.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return polygons.before(a, b); });
    return order;
}

// The rules on one kind of face set, over its sorted handles: the fates, then the third face
// of the earliest place refused, or the faces that go dropped.
template <class FaceSet, class Handle, class Same>
void settle_faces(const FaceSet& faces, const std::vector<Handle>& sorted, Same&& same,
                  PolygonSoup& soup, RepairReport& report) {
    std::vector<Fate> fate(soup.polygon_count(), Fate::kept);
    std::optional<Third> third;
    bool any = false;
    for_each_group(sorted, same, [&](std::span<const Handle> group) {
        any = true;
        const std::optional<Third> t = resolve_group(faces, group, soup, fate);
        if (t && (!third || t->face < third->face)) third = t;
    });
    if (third) refuse(soup, *third);
    if (any) drop(soup, fate, report);
}

}  // namespace

void resolve_coincident_polygons(PolygonSoup& soup, const std::vector<int>& welded,
                                 RepairReport& report) {
    Polygons polygons{{soup}, {}, {0}, {}, {}};
    const std::vector<std::uint32_t> sorted = sorted_polygons(polygons, welded);
    settle_faces(
        polygons, sorted, [&](std::uint32_t a, std::uint32_t b) { return polygons.same_set(a, b); },
        soup, report);
}

void resolve_coincident_faces(PolygonSoup& soup, const std::vector<int>& welded,
                              RepairReport& report) {
    Faces faces{{soup}, {}};
    const std::vector<Record> records = sorted_records(faces, welded);
    settle_faces(faces, records, same_record_set, soup, report);
}

void join_opposite_faces(PolygonSoup& soup, const std::vector<int>& welded, RepairReport& report) {
    Faces faces{{soup}, {}};
    const std::vector<Record> records = sorted_records(faces, welded);
    std::vector<Fate> fate(soup.polygon_count(), Fate::kept);
    bool any = false;
    for_each_group(records, same_record_set, [&](std::span<const Record> group) {
        if (group.size() != 2 || !faces.opposite(group[0], group[1])) return;
        soup.back[group[0].index] = soup.material[group[1].index];
        fate[group[1].index] = Fate::joined;
        any = true;
    });
    if (any) drop(soup, fate, report);
}

}  // namespace hmcr
