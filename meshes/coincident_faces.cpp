// Groups of faces on the same vertices, found by sorting (vertex set, index) records: at 10^6
// faces a hash map's node per face was a seventh of the load.
#include "meshes/coincident_faces.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>

#include "common/error.h"
#include "meshes/validation.h"

namespace hmcr {
namespace {

// Why a face goes (or stays).
enum class Fate : std::uint8_t { kept, duplicate, joined, conflict };

struct Faces {
    const PolygonSoup& soup;
    std::vector<FaceKey> cyclic;  // per polygon: its ids from the smallest, in its order

    // Same vertices in the same cyclic order: the same way; in the reversed order: opposite.
    // (Two faces on one set of 3 or 4 vertices that pass the patch checks are one polygon,
    // either way round; a strict load may hold others, which are neither.)
    bool same_way(std::uint32_t a, std::uint32_t b) const { return same_key(cyclic[a], cyclic[b]); }
    bool opposite(std::uint32_t a, std::uint32_t b) const {
        const FaceKey& k = cyclic[a];
        const bool quad = k[3] != std::numeric_limits<int>::max();
        const FaceKey reversed =
            quad ? FaceKey{k[0], k[3], k[2], k[1]} : FaceKey{k[0], k[2], k[1], k[3]};
        return same_key(reversed, cyclic[b]);
    }

    bool same_material(std::int32_t a, std::int32_t b) const {
        if (a == b) return true;
        if (a < 0 || b < 0) return false;
        const SoupMaterial& x = soup.materials[std::size_t(a)];
        const SoupMaterial& y = soup.materials[std::size_t(b)];
        return x.defined && y.defined && x.material.kd == y.material.kd &&
               x.material.ke == y.material.ke && x.material.ks == y.material.ks &&
               x.material.roughness == y.material.roughness;
    }

    bool copy(std::uint32_t a, std::uint32_t b) const {
        return same_way(a, b) && same_material(soup.material[a], soup.material[b]) &&
               (soup.back[a] == soup.back[b] || same_material(soup.back[a], soup.back[b]));
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

struct Record {
    FaceKey set;  // the sorted ids
    std::uint32_t index;
};

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
        return fmt::format("on lines {} and {}", a.line, b.line);
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

// The fates of one group's faces (records [begin, end) of one vertex set); a third face kept
// is returned, not thrown, so that the earliest of all groups is the one named.
std::optional<Third> resolve_group(const Faces& faces, const Record* begin, const Record* end,
                                   PolygonSoup& soup, std::vector<Fate>& fate) {
    std::uint32_t kept[2];
    std::size_t n = 0;
    for (const Record* r = begin; r != end; ++r) {
        const std::uint32_t f = r->index;
        if (std::any_of(kept, kept + n, [&](std::uint32_t k) { return faces.copy(k, f); })) {
            fate[f] = Fate::duplicate;
        } else if (n == 2) {
            return Third{f, kept[0], kept[1]};
        } else {
            kept[n++] = f;
        }
    }
    if (n < 2) return std::nullopt;
    if (faces.opposite(kept[0], kept[1])) {
        soup.back[kept[0]] = soup.material[kept[1]];
        fate[kept[1]] = Fate::joined;
    } else {
        fate[kept[1]] = Fate::conflict;
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

template <class Group>
void for_each_group(const std::vector<Record>& records, Group&& group) {
    for (std::size_t begin = 0, end = 1; begin < records.size(); begin = end++) {
        while (end < records.size() && same_key(records[end].set, records[begin].set)) ++end;
        if (end - begin >= 2) group(records.data() + begin, records.data() + end);
    }
}

}  // namespace

void resolve_coincident_faces(PolygonSoup& soup, const std::vector<int>& welded,
                              RepairReport& report) {
    Faces faces{soup, {}};
    const std::vector<Record> records = sorted_records(faces, welded);
    std::vector<Fate> fate(soup.polygon_count(), Fate::kept);
    std::optional<Third> third;
    bool any = false;
    for_each_group(records, [&](const Record* begin, const Record* end) {
        any = true;
        const std::optional<Third> t = resolve_group(faces, begin, end, soup, fate);
        if (t && (!third || t->face < third->face)) third = t;
    });
    if (third) refuse(soup, *third);
    if (any) drop(soup, fate, report);
}

void join_opposite_faces(PolygonSoup& soup, const std::vector<int>& welded, RepairReport& report) {
    Faces faces{soup, {}};
    const std::vector<Record> records = sorted_records(faces, welded);
    std::vector<Fate> fate(soup.polygon_count(), Fate::kept);
    bool any = false;
    for_each_group(records, [&](const Record* begin, const Record* end) {
        if (end - begin != 2 || !faces.opposite(begin[0].index, begin[1].index)) return;
        soup.back[begin[0].index] = soup.material[begin[1].index];
        fate[begin[1].index] = Fate::joined;
        any = true;
    });
    if (any) drop(soup, fate, report);
}

}  // namespace hmcr
