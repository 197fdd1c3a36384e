// SPDX-License-Identifier: Apache-2.0
// Ear clipping (Meisters 1975; Eberly, "Triangulation by ear clipping", 2002) in the polygon's
// least-squares plane. Orientation tests use a tolerance relative to the polygon's size, the
// same one the patch checks use for a zero-area corner (meshes/validation.h).
#include "meshes/triangulate.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "meshes/validation.h"

namespace hmcr {
namespace {

using Point2 = Eigen::Vector2d;

// Twice the signed area of triangle abc: > 0 when it turns counter-clockwise.
double turn(const Point2& a, const Point2& b, const Point2& c) {
    const Point2 ab = b - a, ac = c - a;
    return ab.x() * ac.y() - ab.y() * ac.x();
}

Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& p) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) n += p[i].cross(p[(i + 1) % p.size()]);
    return n;
}

// The polygon in its plane, with the tolerance below which a turn counts as zero.
struct Polygon2 {
    std::vector<Point2> p;
    const std::vector<int>& ids;
    double eps = 0;
};

Polygon2 project(const std::vector<Eigen::Vector3d>& corners, const std::vector<int>& ids,
                 const PolygonPlane& plane) {
    Polygon2 out{{}, ids, 0};
    for (const Eigen::Vector3d& c : corners) {
        const Eigen::Vector3d d = c - plane.origin;
        out.p.emplace_back(d.dot(plane.u), d.dot(plane.v));
    }
    const double edge = largest_edge(corners);
    out.eps = 2 * kDegenerateAreaRatio * edge * edge;
    return out;
}

int sign(double x, double eps) { return x > eps ? 1 : x < -eps ? -1 : 0; }

// q lies on segment ab, strictly between its ends.
bool inside_segment(const Point2& q, const Point2& a, const Point2& b, double eps) {
    return sign(turn(a, b, q), eps) == 0 && (q - a).dot(b - a) > 0 && (q - b).dot(a - b) > 0;
}

// Edges i and j (from corner i to i+1) cross, or overlap running the same way. A corner on
// another edge, and two edges along one line in opposite directions, are seams (MGF cuts holes
// that way: an edge there and back, or a hole hung on a corner of the outline) and allowed;
// the triangles' area check catches a seam that made the polygon overlap itself.
bool edges_meet(const Polygon2& g, std::size_t i, std::size_t j) {
    const std::size_t n = g.p.size(), i1 = (i + 1) % n, j1 = (j + 1) % n;
    const int a = g.ids[i], b = g.ids[i1], c = g.ids[j], d = g.ids[j1];
    if (a == c && b == d) return true;  // the same edge twice, same way
    const Point2 &pa = g.p[i], &pb = g.p[i1], &pc = g.p[j], &pd = g.p[j1];
    const int s1 = sign(turn(pa, pb, pc), g.eps), s2 = sign(turn(pa, pb, pd), g.eps);
    const int s3 = sign(turn(pc, pd, pa), g.eps), s4 = sign(turn(pc, pd, pb), g.eps);
    if (s1 * s2 < 0 && s3 * s4 < 0) return true;  // a proper crossing
    if (s1 != 0 || s2 != 0) return false;         // at most touching: a corner on the other edge
    // Along one line: there and back is a seam; the same way, overlapping, is not.
    if ((pb - pa).dot(pd - pc) < 0) return false;
    return inside_segment(pc, pa, pb, g.eps) || inside_segment(pd, pa, pb, g.eps) ||
           inside_segment(pa, pc, pd, g.eps) || inside_segment(pb, pc, pd, g.eps);
}

std::optional<std::string> find_crossing(const Polygon2& g) {
    const std::size_t n = g.p.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            if (edges_meet(g, i, j)) {
                return fmt::format(
                    "self-intersecting polygon: edges {} and {} (from corners {} and "
                    "{}) meet",
                    i + 1, j + 1, i + 1, j + 1);
            }
        }
    }
    return std::nullopt;
}

// The remaining polygon as a doubly linked ring of corner indices.
class EarClipper {
public:
    explicit EarClipper(const Polygon2& g)
        : m_g(g),
          m_prev(g.p.size()),
          m_next(g.p.size()),
          m_removed(g.p.size(), false),
          m_blocker(g.p.size()),
          m_tests_left(kMaxEarTests * g.p.size() * g.p.size()) {
        const std::size_t n = g.p.size();
        for (std::size_t i = 0; i < n; ++i) {
            m_prev[i] = (i + n - 1) % n;
            m_next[i] = (i + 1) % n;
        }
        m_left = n;
    }

    std::optional<std::vector<CornerTriangle>> run() {
        std::size_t i = 0, tries = 0;
        while (m_left > 3) {
            if (exhausted()) return std::nullopt;
            if (is_ear(i)) {
                clip(i);
                tries = 0;
            } else if (++tries > m_left) {
                if (!drop_flat_corner()) return std::nullopt;
                tries = 0;
            }
            i = m_next[i];
        }
        add(m_prev[i], i, m_next[i]);
        return std::move(m_triangles);
    }

    // kMaxEarTests per corner squared were made: the polygon is refused rather than
    // triangulated at any cost. The shapes measured (stars, combs, spirals, random outlines)
    // needed 0.5 to 0.7.
    bool exhausted() const { return m_tests_left == 0; }
    static constexpr std::size_t kMaxEarTests = 4;

private:
    double corner_turn(std::size_t i) const {
        return turn(m_g.p[m_prev[i]], m_g.p[i], m_g.p[m_next[i]]);
    }

    // A corner that blocked i's ear stays a blocker while it and i's neighbours remain, so the
    // answer is remembered: without it a spiral of 10,000 corners took 18 s, each corner's
    // ear tested against every other corner again and again.
    bool is_ear(std::size_t i) {
        if (m_removed[i] || sign(corner_turn(i), m_g.eps) <= 0) return false;
        const std::size_t a = m_prev[i], c = m_next[i];
        Blocker& blocker = m_blocker[i];
        if (blocker.corner != kNone && !m_removed[blocker.corner] && blocker.prev == a &&
            blocker.next == c) {
            return false;
        }
        const int ia = m_g.ids[a], ib = m_g.ids[i], ic = m_g.ids[c];
        for (std::size_t k = m_next[c]; k != a; k = m_next[k]) {
            if (m_tests_left == 0) return false;  // run() gives up
            --m_tests_left;
            const int id = m_g.ids[k];
            if (id == ia || id == ib || id == ic) continue;  // a seam's other copy
            if (blocks(m_g.p[k], m_g.p[a], m_g.p[i], m_g.p[c])) {
                blocker = {k, a, c};
                return false;
            }
        }
        return true;
    }

    // A corner inside the ear abc, or on its new edge ca, forbids cutting it; one on ab or bc
    // (a polygon edge, met again along a seam) does not.
    bool blocks(const Point2& q, const Point2& a, const Point2& b, const Point2& c) const {
        const int s_ab = sign(turn(a, b, q), m_g.eps), s_bc = sign(turn(b, c, q), m_g.eps);
        const int s_ca = sign(turn(c, a, q), m_g.eps);
        if (s_ab > 0 && s_bc > 0 && s_ca > 0) return true;
        return s_ca == 0 && s_ab >= 0 && s_bc >= 0 && inside_segment(q, c, a, m_g.eps);
    }

    void add(std::size_t a, std::size_t b, std::size_t c) {
        if (sign(turn(m_g.p[a], m_g.p[b], m_g.p[c]), m_g.eps) > 0) m_triangles.push_back({a, b, c});
    }

    void unlink(std::size_t i) {
        m_next[m_prev[i]] = m_next[i];
        m_prev[m_next[i]] = m_prev[i];
        m_removed[i] = true;
        --m_left;
    }

    void clip(std::size_t i) {
        add(m_prev[i], i, m_next[i]);
        unlink(i);
    }

    // No ear left: only a corner with no turn (its triangle has no area) may go.
    bool drop_flat_corner() {
        for (std::size_t k = 0; k < m_g.p.size(); ++k) {
            if (!m_removed[k] && sign(corner_turn(k), m_g.eps) == 0) {
                unlink(k);
                return true;
            }
        }
        return false;
    }

    static constexpr std::size_t kNone = std::size_t(-1);
    // The corner found inside a corner's ear, with the neighbours the ear had then.
    struct Blocker {
        std::size_t corner = kNone, prev = kNone, next = kNone;
    };

    const Polygon2& m_g;
    std::vector<std::size_t> m_prev, m_next;
    std::vector<bool> m_removed;
    std::vector<Blocker> m_blocker;
    std::size_t m_tests_left;  // corners that ears may still be tested against
    std::size_t m_left = 0;
    std::vector<CornerTriangle> m_triangles;
};

double signed_area(const std::vector<Point2>& p) {
    double twice = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        twice += turn(Point2::Zero(), p[i], p[(i + 1) % p.size()]);
    return 0.5 * twice;
}

// The triangles must cover the polygon's area exactly: a sum that differs means an ear was
// cut outside the polygon (a seam around a corner it should not cross).
bool covers_area(const Polygon2& g, const std::vector<CornerTriangle>& triangles) {
    double sum = 0;
    for (const CornerTriangle& t : triangles) sum += 0.5 * turn(g.p[t[0]], g.p[t[1]], g.p[t[2]]);
    const double area = signed_area(g.p);
    return std::abs(sum - area) <= 1e-9 * std::abs(area) + g.eps * double(g.p.size());
}

}  // namespace

std::string too_many_corners(std::size_t corners) {
    return fmt::format("polygon with {} corners: at most {} are triangulated", corners,
                       kMaxPolygonCorners);
}

std::optional<PolygonPlane> best_fit_plane(const std::vector<Eigen::Vector3d>& corners) {
    const Eigen::Vector3d newell = newell_normal(corners);
    const double edge = largest_edge(corners);
    if (!(newell.norm() > 2 * kDegenerateAreaRatio * edge * edge)) return std::nullopt;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& c : corners) centroid += c;
    centroid /= double(corners.size());
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& c : corners) spread += (c - centroid) * (c - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(spread);
    Eigen::Vector3d normal = solver.eigenvectors().col(0);  // the smallest eigenvalue's
    if (normal.dot(newell) < 0) normal = -normal;
    if (!(normal.dot(newell.normalized()) > 1e-3)) normal = newell.normalized();  // a needle
    const Eigen::Vector3d u = normal.unitOrthogonal();
    return PolygonPlane{centroid, u, normal.cross(u), normal};
}

Triangulation triangulate(const std::vector<Eigen::Vector3d>& corners,
                          const std::vector<int>& ids) {
    if (corners.size() > kMaxPolygonCorners) return {{}, too_many_corners(corners.size())};
    const std::optional<PolygonPlane> plane = best_fit_plane(corners);
    if (!plane) return {{}, "self-intersecting polygon: it has no area or winds both ways"};
    const Polygon2 g = project(corners, ids, *plane);
    if (auto crossing = find_crossing(g)) return {{}, *crossing};
    EarClipper clipper(g);
    std::optional<std::vector<CornerTriangle>> triangles = clipper.run();
    if (clipper.exhausted()) {
        return {{},
                fmt::format("polygon too intricate to triangulate: more than {} x {}^2 ear "
                            "tests",
                            EarClipper::kMaxEarTests, corners.size())};
    }
    if (!triangles || !covers_area(g, *triangles)) {
        return {{},
                "polygon cannot be triangulated in its best-fit plane (it overlaps itself "
                "there)"};
    }
    return {std::move(*triangles), {}};
}

double projected_area(const std::vector<Eigen::Vector3d>& corners) {
    const std::optional<PolygonPlane> plane = best_fit_plane(corners);
    if (!plane) return 0;
    std::vector<int> ids(corners.size());
    return signed_area(project(corners, ids, *plane).p);
}

}  // namespace hmcr
