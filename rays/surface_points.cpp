// SPDX-License-Identifier: Apache-2.0
#include "rays/surface_points.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rays/rng.h"

namespace hmcr {
namespace {

// Keys the strata's jitter apart from every other stream (docs/design.md §9.1).
constexpr std::uint64_t kStrataKey = 0x737472617461ULL;  // "strata"

// Cuts per edge are capped so that a stratum count stays far from overflow; a side then has
// at most 2^40 points, which no memory check lets through.
constexpr double kMostCuts = double(1 << 20);

std::uint32_t cuts(double x) { return std::uint32_t(std::clamp(std::round(x), 1.0, kMostCuts)); }

// Uniform in the triangle (p0, p1, p2) of the parameter plane.
Vec2 in_triangle(const Vec2& p0, const Vec2& p1, const Vec2& p2, double xi1, double xi2) {
    const double r = std::sqrt(xi1);
    return (1 - r) * p0 + r * (1 - xi2) * p1 + r * xi2 * p2;
}

void fill_side(const Patch& patch, std::uint32_t index, std::uint8_t side, const SideStrata& k,
               std::uint64_t strata_seed, SurfacePoint* out) {
    Rng rng(kStrataKey + strata_seed, index, side);
    std::uint64_t n = 0;
    if (patch.is_quad()) {
        const double cell = 1.0 / (double(k.ku) * double(k.kv));
        for (std::uint32_t j = 0; j < k.kv; ++j) {
            for (std::uint32_t i = 0; i < k.ku; ++i) {
                const double xi1 = rng.uniform(), xi2 = rng.uniform();
                const Vec2 uv((i + xi1) / k.ku, (j + xi2) / k.kv);
                out[n++] = {patch.point(uv), patch.jacobian(uv) * cell, index, side};
            }
        }
        return;
    }
    // k^2 congruent sub-triangles of the unit triangle: in row b, k - b upright ones and
    // k - b - 1 inverted ones between them.
    const double kk = k.ku, weight = patch.area / (kk * kk);
    for (std::uint32_t b = 0; b < k.ku; ++b) {
        for (std::uint32_t a = 0; a + b < k.ku; ++a) {
            const Vec2 c(a / kk, b / kk), du(1 / kk, 0), dv(0, 1 / kk);
            for (int inverted = 0; inverted < (a + b + 1 < k.ku ? 2 : 1); ++inverted) {
                const double xi1 = rng.uniform(), xi2 = rng.uniform();
                const Vec2 uv = inverted ? in_triangle(c + du + dv, c + dv, c + du, xi1, xi2)
                                         : in_triangle(c, c + du, c + dv, xi1, xi2);
                out[n++] = {patch.point(uv), weight, index, side};
            }
        }
    }
}

// The strata of every side in output order, and where each side's points start.
struct Layout {
    std::vector<SideStrata> strata;  // 2 per patch: front, back (count 0 for a missing back)
    std::vector<std::uint64_t> first;
};

Layout layout(const PatchSet& set, std::uint64_t target) {
    if (target < 1) throw std::invalid_argument("stratified_points: the target must be >= 1");
    const double a = set.total_area / double(target);
    Layout l;
    const std::size_t n = set.patches.size();
    l.strata.resize(2 * n);
    l.first.assign(2 * n + 1, 0);
    for (std::size_t p = 0; p < n; ++p) {
        const Patch& patch = set.patches[p];
        const SideStrata k = side_strata(patch, a);
        l.strata[2 * p] = k;
        l.first[2 * p + 1] = l.first[2 * p] + k.count(patch.is_quad());
        const bool back = set.two_sided(p);
        if (back) l.strata[2 * p + 1] = k;
        l.first[2 * p + 2] = l.first[2 * p + 1] + (back ? k.count(patch.is_quad()) : 0);
    }
    return l;
}

}  // namespace

SideStrata side_strata(const Patch& patch, double area_per_point) {
    const double n = patch.area / area_per_point;  // points the side should get
    if (!patch.is_quad()) {
        const std::uint32_t k = cuts(std::sqrt(n));
        return {k, k};
    }
    const auto& c = patch.corner;
    const double lu = 0.5 * ((c[1] - c[0]).norm() + (c[2] - c[3]).norm());
    const double lv = 0.5 * ((c[3] - c[0]).norm() + (c[2] - c[1]).norm());
    const double aspect = lv > 0 ? lu / lv : 1;
    return {cuts(std::sqrt(n * aspect)), cuts(std::sqrt(n / aspect))};
}

std::uint64_t stratified_point_count(const PatchSet& set, std::uint64_t target) {
    return layout(set, target).first.back();
}

std::vector<SurfacePoint> stratified_points(const PatchSet& set, std::uint64_t target,
                                            std::uint64_t strata_seed) {
    const Layout l = layout(set, target);
    std::vector<SurfacePoint> out(l.first.back());
    tbb::parallel_for(std::size_t(0), set.patches.size(), [&](std::size_t p) {
        for (std::uint8_t side : {kFront, kBack}) {
            const std::size_t s = 2 * p + side;
            if (l.first[s + 1] == l.first[s]) continue;
            fill_side(set.patches[p], std::uint32_t(p), side, l.strata[s], strata_seed,
                      &out[l.first[s]]);
        }
    });
    return out;
}

}  // namespace hmcr
