// SPDX-License-Identifier: Apache-2.0
// The repair pass: per polygon, take out repeated and collinear corners and drop what has no area
// left; settle the faces of 5 corners or more on the same vertices; per polygon, cut what is not
// a triangle or a planar convex quad into triangles; then settle the faces on the same vertices
// (meshes/coincident_faces.h), and accept reflectance 1.
#include "meshes/repairs.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <set>

#include "meshes/coincident_faces.h"
#include "meshes/triangulate.h"
#include "meshes/validation.h"
#include "meshes/weld.h"

namespace hmcr {
namespace {

// One polygon's corners: soup position indices, welded ids and positions.
struct Corners {
    std::vector<std::uint32_t> soup;
    std::vector<int> ids;
    std::vector<Eigen::Vector3d> p;

    std::size_t size() const { return soup.size(); }
    void erase(std::size_t i) {
        soup.erase(soup.begin() + std::ptrdiff_t(i));
        ids.erase(ids.begin() + std::ptrdiff_t(i));
        p.erase(p.begin() + std::ptrdiff_t(i));
    }
    Corners pick(std::initializer_list<std::size_t> which) const {
        Corners out;
        for (std::size_t i : which) {
            out.soup.push_back(soup[i]);
            out.ids.push_back(ids[i]);
            out.p.push_back(p[i]);
        }
        return out;
    }
};

// Polygon k's corners into c, reusing its storage (a million polygons, not 3 million vectors).
void corners_of(const PolygonSoup& soup, std::size_t k, const std::vector<int>& welded,
                Corners& c) {
    c.soup.clear();
    c.ids.clear();
    c.p.clear();
    for (std::uint32_t s : soup.corners(k)) {
        c.soup.push_back(s);
        c.ids.push_back(welded[s]);
        c.p.push_back(soup.positions[s]);
    }
}

// Corner i repeats the next one, or spans no area with its neighbours (the tolerance of the
// patch checks, relative to the polygon's largest edge).
bool corner_is_degenerate(const Corners& c, std::size_t i, double limit) {
    const std::size_t n = c.size(), prev = (i + n - 1) % n, next = (i + 1) % n;
    if (c.ids[i] == c.ids[next]) return true;
    return 0.5 * (c.p[i] - c.p[prev]).cross(c.p[next] - c.p[i]).norm() < limit;
}

// Takes such corners out until none is left; true when any was.
bool remove_degenerate_corners(Corners& c) {
    const double edge = largest_edge(c.p);
    const double limit = kDegenerateAreaRatio * edge * edge;
    bool removed = false, changed = true;
    while (changed) {
        changed = false;
        for (std::size_t i = 0; c.size() >= 3 && i < c.size();) {
            if (!corner_is_degenerate(c, i, limit)) {
                ++i;
                continue;
            }
            c.erase(i);
            removed = changed = true;
        }
    }
    return removed;
}

Eigen::Vector3d triangle_normal(const Corners& c, std::size_t a, std::size_t b, std::size_t d) {
    return (c.p[b] - c.p[a]).cross(c.p[d] - c.p[a]);
}

// Split along diagonal 0-2 (first) or 1-3: both halves must face the way the quad does.
std::optional<std::vector<Corners>> split_quad(const Corners& c) {
    const Eigen::Vector3d facing = triangle_normal(c, 0, 1, 2) + triangle_normal(c, 0, 2, 3);
    const auto valid = [&](std::size_t a) {
        const std::size_t b = (a + 1) % 4, d = (a + 2) % 4, e = (a + 3) % 4;
        return triangle_normal(c, a, b, d).dot(facing) > 0 &&
               triangle_normal(c, a, d, e).dot(facing) > 0;
    };
    const bool first_shorter = (c.p[2] - c.p[0]).norm() <= (c.p[3] - c.p[1]).norm();
    for (std::size_t a :
         first_shorter ? std::array<std::size_t, 2>{0, 1} : std::array<std::size_t, 2>{1, 0}) {
        if (valid(a))
            return std::vector<Corners>{c.pick({a, (a + 1) % 4, (a + 2) % 4}),
                                        c.pick({a, (a + 2) % 4, (a + 3) % 4})};
    }
    return std::nullopt;
}

// The place of a polygon, formatted only when a repair or an error names it (a million
// faces must not mean a million formatted "file:line" strings).
struct Where {
    const PolygonSoup& soup;
    SourcePlace place;
    operator std::string() const { return soup.where(place); }
};

std::vector<Corners> ear_clip(const Corners& c, const Where& where) {
    const Triangulation t = triangulate(c.p, c.ids);
    if (!t.error.empty()) throw InputError(std::string(where), t.error);
    std::vector<Corners> out;
    for (const CornerTriangle& tri : t.triangles) out.push_back(c.pick({tri[0], tri[1], tri[2]}));
    return out;
}

// Takes the repeated and collinear corners out of polygon c, or drops it (false) when fewer
// than 3 are left.
bool remove_corners(Corners& c, const Where& where, RepairReport& report) {
    if (!remove_degenerate_corners(c)) return true;
    if (c.size() < 3) {
        report.add(RepairKind::degenerate_dropped, where);
        return false;
    }
    report.add(RepairKind::corners_removed, where);
    return true;
}

enum class Cut { whole, pieces };

// What a polygon without degenerate corners becomes (itself, or `pieces`).
Cut cut_polygon(const Corners& c, const Where& where, RepairReport& report,
                std::vector<Corners>& pieces) {
    if (c.size() == 3 || (c.size() == 4 && !check_face_geometry(c.p, c.ids))) return Cut::whole;
    if (c.size() == 4 && !quad_is_planar(c.p)) {
        std::optional<std::vector<Corners>> halves = split_quad(c);
        if (!halves)
            throw InputError(std::string(where), "self-intersecting quad: its edges cross");
        report.add(RepairKind::quad_split, where);
        pieces = std::move(*halves);
        return Cut::pieces;
    }
    report.add(RepairKind::triangulated, where);
    pieces = ear_clip(c, where);
    return Cut::pieces;
}

// The soup's polygons replaced by what `make` turns each into: make(c, k, out) adds polygon k's
// pieces (c its corners) to out.
template <class Make>
void rebuild(PolygonSoup& soup, const std::vector<int>& welded, Make&& make) {
    PolygonSoup out;
    Corners c;
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        corners_of(soup, k, welded, c);
        make(c, k, out);
    }
    soup.corner_offsets = std::move(out.corner_offsets);
    soup.corner_ids = std::move(out.corner_ids);
    soup.material = std::move(out.material);
    soup.back = std::move(out.back);
    soup.place = std::move(out.place);
}

// Whether a face (either side) uses each of the soup's materials.
std::vector<bool> used_materials(const PolygonSoup& soup) {
    std::vector<bool> used(soup.materials.size(), false);
    for (const auto* ids : {&soup.material, &soup.back}) {
        for (std::int32_t m : *ids) {
            if (m >= 0) used[std::size_t(m)] = true;
        }
    }
    return used;
}

// An MGF material whose rd + rs is above 1 in a channel (RenderPark's scenes write up to 1.3):
// its specular part is scaled down until the sum's largest channel is 0.99, as a coloured rd
// alone is fitted (meshes/mgf_reader.cpp). rd, which the radiosity engine uses, stays; only the
// path tracer's glossy lobe is dimmer than written.
void reduce_specular(PolygonSoup& soup, RepairReport& report) {
    constexpr double kFit = 0.99;
    const std::vector<bool> used = used_materials(soup);
    std::set<std::string> told;  // one material read twice (MGF) is told once
    for (std::size_t m = 0; m < soup.materials.size(); ++m) {
        SoupMaterial& sm = soup.materials[m];
        Material& mat = sm.material;
        if (!used[m] || !sm.specular_reducible || (mat.kd + mat.ks).maxCoeff() <= 1) continue;
        if (!mat.ks.allFinite() || mat.ks.minCoeff() < 0 || mat.kd.maxCoeff() > 1) continue;
        double scale = 1;
        for (int k = 0; k < 3; ++k) {
            if (mat.ks[k] > 0) scale = std::min(scale, std::max(0.0, kFit - mat.kd[k]) / mat.ks[k]);
        }
        mat.ks *= scale;
        const std::string where = soup.where(sm.ks);
        if (told.insert(where).second) report.add(RepairKind::specular_reduced, where);
    }
}

void accept_reflectance_one(PolygonSoup& soup, RepairReport& report) {
    const std::vector<bool> used = used_materials(soup);
    std::set<std::string> told;  // one material read twice (MGF) is told once
    for (std::size_t m = 0; m < soup.materials.size(); ++m) {
        const SoupMaterial& sm = soup.materials[m];
        // Kd + Ks: a mirror of reflectance 1 absorbs nothing either (Ks is 0 without one)
        const Eigen::Vector3d total = sm.material.kd + sm.material.ks;
        if (!used[m] || !sm.defined || total.maxCoeff() != 1.0 || total.minCoeff() < 0) continue;
        const std::string where = soup.where(sm.material.ks.maxCoeff() > 0 ? sm.ks : sm.kd);
        if (!told.insert(where).second) continue;
        report.add(RepairKind::reflectance_one, where);
        soup.warnings.push_back(fmt::format(
            "{}: reflectance 1 of material {} accepted: it absorbs no light, so a closed scene "
            "may run out of rays before the stop rule",
            where, quote(sm.material.name)));
    }
}

}  // namespace

RepairReport repair_soup(PolygonSoup& soup) { return repair_soup(soup, weld(soup.positions)); }

RepairReport repair_soup(PolygonSoup& soup, const Welding& welding) {
    RepairReport report;
    const std::vector<int>& welded = welding.id;
    const auto keep = [&](const Corners& c, std::size_t k, PolygonSoup& out) {
        out.add_polygon(c.soup, soup.material[k], soup.place[k], soup.back[k]);
    };
    // The corners first, so that faces of 5 or more are compared as what they are, then cut.
    rebuild(soup, welded, [&](Corners& c, std::size_t k, PolygonSoup& out) {
        if (remove_corners(c, Where{soup, soup.place[k]}, report)) keep(c, k, out);
    });
    resolve_coincident_polygons(soup, welded, report);
    std::vector<Corners> pieces;
    rebuild(soup, welded, [&](Corners& c, std::size_t k, PolygonSoup& out) {
        if (cut_polygon(c, Where{soup, soup.place[k]}, report, pieces) == Cut::whole) {
            keep(c, k, out);
        } else {
            for (const Corners& piece : pieces) keep(piece, k, out);
        }
    });
    resolve_coincident_faces(soup, welded, report);
    reduce_specular(soup, report);
    accept_reflectance_one(soup, report);
    return report;
}

RepairReport join_opposite_faces(PolygonSoup& soup, const Welding& welding) {
    RepairReport report;
    join_opposite_faces(soup, welding.id, report);
    return report;
}

}  // namespace hmcr
