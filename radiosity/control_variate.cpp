#include "radiosity/control_variate.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <utility>

namespace hmcr {
namespace {

struct Box {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    double diagonal() const { return (hi - lo).norm(); }
};

Box bounding_box(const PatchSet& ps) {
    Box b;
    for (const Patch& p : ps.patches) {
        for (int k = 0; k < p.corner_count; ++k) {
            b.lo = b.lo.cwiseMin(p.corner[k]);
            b.hi = b.hi.cwiseMax(p.corner[k]);
        }
    }
    return b;
}

// Points within this of a plane count as on it: 10^-9 of the scene's size, far below the
// self-hit offset (§3.3).
double plane_tolerance(const Box& b) { return 1e-9 * b.diagonal(); }

// The largest signed distance of p's corners from the plane through `origin` along `normal`.
double farthest_along(const Patch& p, const Vec3& origin, const Vec3& normal) {
    double d = -1e300;
    for (int k = 0; k < p.corner_count; ++k) d = std::max(d, normal.dot(p.corner[k] - origin));
    return d;
}

bool reflects(const PatchMaterial& m) { return (m.reflectance > 0).any(); }

// Whether side (q, side) of reflectance > 0 may see the back of one-sided patch p: both must
// have a corner strictly in front of the other (a necessary condition for F > 0).
bool may_see_back(const PatchSet& ps, std::size_t q, std::uint8_t side, std::size_t p,
                  double tol) {
    const Patch& pp = ps.patches[p];
    const Patch& pq = ps.patches[q];
    return farthest_along(pq, pp.corner[0], -pp.normal) > tol &&
           farthest_along(pp, pq.corner[0], side_normal(pq, side)) > tol;
}

bool back_may_be_seen(const PatchSet& ps, std::size_t p, double tol) {
    for (std::size_t q = 0; q < ps.patches.size(); ++q) {
        if (q == p) continue;
        for (std::uint8_t side : {kFront, kBack}) {
            if (side == kBack && !ps.two_sided(q)) continue;
            if (reflects(ps.material(q, side)) && may_see_back(ps, q, side, p, tol)) return true;
        }
    }
    return false;
}

// Face f of a box: axis f / 2, at its low (f even) or high end; its corners counter-clockwise
// seen from inside, so that its normal points inward.
Patch box_face(const Vec3& lo, const Vec3& hi, int f) {
    const int axis = f / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
    Patch p;
    p.corner_count = 4;
    for (int k = 0; k < 4; ++k) {
        p.corner[k][axis] = f % 2 ? hi[axis] : lo[axis];
        p.corner[k][a] = (k == 1 || k == 2) ? hi[a] : lo[a];
        p.corner[k][b] = (k >= 2) ? hi[b] : lo[b];
    }
    p.finalize();
    if (p.normal.dot(0.5 * (lo + hi) - p.corner[0]) < 0) {
        std::swap(p.corner[1], p.corner[3]);
        p.finalize();
    }
    return p;
}

// Whether no side with reflectance > 0 sees the background through face f of the scene's
// bounding box: the patches in its plane cover it (no ray from inside leaves through it), and
// none of them turns a side of reflectance > 0 outward.
bool face_closed(const PatchSet& ps, const Patch& face, int f, double tol) {
    const int axis = f / 2;
    const double x = face.corner[0][axis];
    double covered = 0;
    for (std::size_t q = 0; q < ps.patches.size(); ++q) {
        const Patch& p = ps.patches[q];
        bool on = true;
        for (int k = 0; k < p.corner_count; ++k) on &= std::abs(p.corner[k][axis] - x) <= tol;
        if (!on) continue;
        covered += p.area;
        const std::uint8_t outward = p.normal.dot(face.normal) < 0 ? kFront : kBack;
        if (outward == kFront || ps.two_sided(q)) {
            if (reflects(ps.material(q, outward))) return false;
        }
    }
    return covered >= face.area * (1 - 1e-9);
}

// The beta minimising (P + z |beta|) (P + seen z |beta|), P(beta) = sum_j A_j |v_j - beta| over
// `values` (v_j, A_j) and z the zero surfaces' area (§3.11). Between consecutive values and 0
// both factors are linear and positive, so their product is monotone or concave there: its
// minimum is at one of those points. 0 wins ties (the plain iteration).
double best_constant(std::vector<std::pair<double, double>>& values, double z, double seen) {
    values.emplace_back(0.0, 0.0);  // 0 is a corner of |beta|
    std::sort(values.begin(), values.end());
    double total_a = 0, total_av = 0;
    for (const auto& [v, a] : values) total_a += a, total_av += a * v;
    double best = 0, best_cost = HUGE_VAL, zero_cost = HUGE_VAL;
    double below_a = 0, below_av = 0;  // of the values before k
    for (const auto& [x, a] : values) {
        const double p = (below_a * x - below_av) + ((total_av - below_av) - (total_a - below_a) * x);
        const double cost = (p + z * std::abs(x)) * (p + seen * z * std::abs(x));
        if (x == 0) zero_cost = std::min(zero_cost, cost);
        if (cost < best_cost) best = x, best_cost = cost;
        below_a += a;
        below_av += a * x;
    }
    return zero_cost <= best_cost ? 0.0 : best;
}

}  // namespace

std::vector<Patch> background_faces(const PatchSet& ps) {
    const Box b = bounding_box(ps);
    const double tol = plane_tolerance(b);
    std::vector<Patch> open;
    for (int f = 0; f < 6; ++f) {
        const Patch face = box_face(b.lo, b.hi, f);
        if (face.area > tol * tol && face_closed(ps, face, f, tol)) continue;
        // Moved out by ten self-hit offsets (§3.3), so that its rays meet the patches in the
        // face's plane.
        Patch moved = face;
        for (Vec3& c : moved.corner) c -= 1e-5 * b.diagonal() * face.normal;
        moved.finalize();
        open.push_back(moved);
    }
    return open;
}

ZeroSurfaces::ZeroSurfaces(const PatchSet& ps) : patches(ps.patches), scene_patches(ps.patches.size()) {
    const Box b = bounding_box(ps);
    const double tol = plane_tolerance(b);
    for (std::size_t p = 0; p < ps.patches.size(); ++p) {
        if (ps.two_sided(p) || !back_may_be_seen(ps, p, tol)) continue;
        backs.push_back(std::uint32_t(p));
        area += ps.patches[p].area;
    }
    for (const Patch& f : background_faces(ps)) {
        patches.push_back(f);
        area += f.area;
    }
}

Rgb control_constant(const Hierarchy& h, const ZeroSurfaces& zero) {
    Rgb beta = Rgb::Zero();
    std::vector<std::pair<double, double>> values;
    for (int c = 0; c < 3; ++c) {
        values.clear();
        h.for_each_leaf([&](const Element& e) { values.emplace_back(e.unshot[c], e.area); });
        beta[c] = best_constant(values, zero.area, zero.seen);
    }
    return beta;
}

void add_constant(Hierarchy& h, const Rgb& beta) {
    h.for_each_element([&](Element& e) {
        const Rgb add = h.material(e).reflectance * beta;
        e.radiosity += add;
        e.unshot += add;
    });
}

}  // namespace hmcr
