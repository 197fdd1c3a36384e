// SPDX-License-Identifier: Apache-2.0
#include "radiosity/control_variate.h"

#include <algorithm>
#include <array>
#include <cmath>
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
bool may_see_back(const PatchSet& ps, std::size_t q, std::uint8_t side, std::size_t p, double tol) {
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

// The area-weighted median of `values` (v_j, A_j) with `zero_weight` more at 0. The medians
// (the minimisers of sum_j A_j |v_j - beta|) are an interval [a, b]: of them, the one nearest 0,
// so that a tie keeps the plain iteration (§3.11).
double weighted_median(std::vector<std::pair<double, double>>& values, double zero_weight) {
    values.emplace_back(0.0, zero_weight);
    std::sort(values.begin(), values.end());
    double total = 0;
    for (const auto& [v, a] : values) total += a;
    double below = 0;
    for (std::size_t k = 0; k < values.size(); ++k) {
        below += values[k].second;
        if (below < 0.5 * total) continue;
        const double a = values[k].first;
        const double b = below > 0.5 * total || k + 1 == values.size() ? a : values[k + 1].first;
        return std::clamp(0.0, a, b);
    }
    return 0;
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

ZeroSurfaces::ZeroSurfaces(const PatchSet& ps)
    : patches(ps.patches), scene_patches(ps.patches.size()) {
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
        beta[c] = weighted_median(values, std::sqrt(zero.seen) * zero.area);
    }
    return beta;
}

std::uint64_t zero_surface_rays(std::uint64_t rays, double sides_power, double zero_power,
                                double seen) {
    if (zero_power <= 0 || rays == 0) return 0;
    if (sides_power <= 0) return rays;
    const double share = zero_power / (sides_power + zero_power);
    const double best = std::sqrt(seen) * zero_power / (sides_power + std::sqrt(seen) * zero_power);
    const auto n = std::uint64_t(std::llround(double(rays) * std::max(best, 0.01 * share)));
    return std::clamp<std::uint64_t>(n, 1, rays > 1 ? rays - 1 : 1);
}

void add_constant(Hierarchy& h, const Rgb& beta) {
    h.for_each_element([&](Element& e) {
        const Rgb add = h.material(e).reflectance * beta;
        e.radiosity += add;
        e.unshot += add;
    });
}

}  // namespace hmcr
