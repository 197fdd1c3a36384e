// SPDX-License-Identifier: Apache-2.0
// The ray generator of rays/ray_generator.h. The vector kernel is compiled once per instruction
// set Highway knows (hwy/foreach_target.h includes this file again for each) and the widest the
// machine supports is chosen when the program runs. Every operation is one IEEE operation per
// lane (no fused multiply-add, no approximate reciprocal), so all widths give the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "rays/ray_generator.cpp"
#include "rays/ray_generator.h"

#include <hwy/foreach_target.h>  // must come before hwy/highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "common/populated.h"
#include "rays/rng.h"
#include "rays/sampling.h"

#ifndef HMCR_RAY_GENERATOR_SHARED
#define HMCR_RAY_GENERATOR_SHARED
namespace hmcr::ray_generator {

// Patch fields as the gathers read them: offsets in doubles from the start of a Patch.
struct PatchLayout {
    std::int64_t stride, corner, normal;
};
inline PatchLayout patch_layout() {
    static_assert(sizeof(Patch) % sizeof(double) == 0);
    const Patch p;
    const auto at = [&](const void* field) {
        return std::int64_t(static_cast<const char*>(field) - reinterpret_cast<const char*>(&p)) /
               std::int64_t(sizeof(double));
    };
    return {std::int64_t(sizeof(Patch) / sizeof(double)), at(p.corner[0].data()),
            at(p.normal.data())};
}

}  // namespace hmcr::ray_generator
#endif

HWY_BEFORE_NAMESPACE();
namespace hmcr::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace rg = hmcr::ray_generator;

using D = hn::ScalableTag<double>;
using DU = hn::RebindToUnsigned<D>;
using DI = hn::RebindToSigned<D>;
using V = hn::Vec<D>;
using VU = hn::Vec<DU>;
using VI = hn::Vec<DI>;

// SplitMix64's finaliser (rays/rng.h) in every lane.
HWY_INLINE VU mix(DU du, VU z) {
    z = hn::Mul(hn::Xor(z, hn::ShiftRight<30>(z)), hn::Set(du, 0xbf58476d1ce4e5b9ULL));
    z = hn::Mul(hn::Xor(z, hn::ShiftRight<27>(z)), hn::Set(du, 0x94d049bb133111ebULL));
    return hn::Xor(z, hn::ShiftRight<31>(z));
}

// Rng(seed, key, index) of every lane, and its next uniform in [0, 1).
struct Streams {
    static constexpr std::uint64_t kGamma = 0x9e3779b97f4a7c15ULL;
    VU state;

    Streams(DU du, std::uint64_t seed, std::uint64_t key, VU index) {
        const VU a = mix(du, hn::Set(du, seed + kGamma));
        const VU b = mix(du, hn::Xor(a, hn::Set(du, key + 2 * kGamma)));
        state = mix(du, hn::Xor(b, hn::Add(index, hn::Set(du, 3 * kGamma))));
    }
    VU next(DU du) {
        state = hn::Add(state, hn::Set(du, kGamma));
        return mix(du, state);
    }
    V uniform(DU du) { return to_unit(hn::ShiftRight<11>(next(du))); }
    // 53 bits as a fraction in [0, 1).
    static V to_unit(VU bits) {
        const D d;
        const DI di;
        return hn::Mul(hn::ConvertTo(d, hn::BitCast(di, bits)), hn::Set(d, 0x1.0p-53));
    }
};

using DU32 = hn::Rebind<std::uint32_t, DU>;
using VU32 = hn::Vec<DU32>;

// rays/sobol.h's owen_scramble in every lane.
template <int kShift>
HWY_INLINE VU32 swap_digits(DU32 du32, VU32 x, std::uint32_t mask) {
    const VU32 m = hn::Set(du32, mask);
    return hn::Or(hn::And(hn::ShiftRight<kShift>(x), m), hn::ShiftLeft<kShift>(hn::And(x, m)));
}
HWY_INLINE VU32 reverse_bits(DU32 du32, VU32 x) {
    x = swap_digits<1>(du32, x, 0x55555555u);
    x = swap_digits<2>(du32, x, 0x33333333u);
    x = swap_digits<4>(du32, x, 0x0f0f0f0fu);
    x = swap_digits<8>(du32, x, 0x00ff00ffu);
    return hn::RotateRight<16>(x);
}
HWY_INLINE VU32 owen_scramble(DU32 du32, VU32 x, VU32 seed) {
    x = hn::Add(reverse_bits(du32, x), seed);
    for (const std::uint32_t c : kOwenMultipliers) x = hn::Xor(x, hn::Mul(x, hn::Set(du32, c)));
    return reverse_bits(du32, x);
}

// Density proportional to (1 - x) a + x b on [0, 1] (rays/sampling.h's sample_linear).
HWY_INLINE V linear(D d, V a, V b, V xi) {
    const V one = hn::Set(d, 1.0);
    const V root =
        hn::Sqrt(hn::Add(hn::Mul(hn::Mul(hn::Sub(one, xi), a), a), hn::Mul(hn::Mul(xi, b), b)));
    const V x = hn::Div(hn::Mul(xi, hn::Add(a, b)), hn::Add(a, root));
    return hn::IfThenElse(hn::Eq(a, b), xi, x);
}

HWY_INLINE V horner(D d, V x2, const double* c, std::size_t n) {
    V r = hn::Set(d, c[n - 1]);
    for (std::size_t k = n - 1; k-- > 0;) r = hn::Add(hn::Mul(r, x2), hn::Set(d, c[k]));
    return r;
}

// cos and sin of 2 pi xi, xi in [0, 1): the quarter turn floor(4 xi) and an angle within
// pi/4 of its middle, whose series converge fast.
HWY_INLINE void cos_sin_turn(D d, V xi, V& cos_out, V& sin_out) {
    const DI di;
    const V four_xi = hn::Mul(xi, hn::Set(d, 4.0));
    const V quarter = hn::Floor(four_xi);
    const V theta =
        hn::Mul(hn::Sub(hn::Sub(four_xi, quarter), hn::Set(d, 0.5)), hn::Set(d, kQuarterTurn));
    const V t2 = hn::Mul(theta, theta);
    const V c = horner(d, t2, kTurnCos.data(), kTurnCos.size());
    const V s = hn::Mul(theta, horner(d, t2, kTurnSin.data(), kTurnSin.size()));
    const V half_root2 = hn::Set(d, kHalfRoot2);
    const V c1 = hn::Mul(hn::Sub(c, s), half_root2);  // cos(pi/4 + theta)
    const V s1 = hn::Mul(hn::Add(s, c), half_root2);  // sin(pi/4 + theta)
    const VI q = hn::ConvertTo(di, quarter);
    const auto odd = hn::RebindMask(d, hn::Eq(hn::And(q, hn::Set(di, 1)), hn::Set(di, 1)));
    const auto upper = hn::RebindMask(d, hn::Gt(q, hn::Set(di, 1)));
    // A quarter turn maps (c, s) to (-s, c): odd quarters swap, the upper half negates.
    V cq = hn::IfThenElse(odd, hn::Neg(s1), c1);
    V sq = hn::IfThenElse(odd, c1, s1);
    cos_out = hn::IfThenElse(upper, hn::Neg(cq), cq);
    sin_out = hn::IfThenElse(upper, hn::Neg(sq), sq);
}

HWY_INLINE V dot3(const V a[3], const V b[3]) {
    return hn::Add(hn::Add(hn::Mul(a[0], b[0]), hn::Mul(a[1], b[1])), hn::Mul(a[2], b[2]));
}
HWY_INLINE void cross3(const V a[3], const V b[3], V out[3]) {
    out[0] = hn::Sub(hn::Mul(a[1], b[2]), hn::Mul(a[2], b[1]));
    out[1] = hn::Sub(hn::Mul(a[2], b[0]), hn::Mul(a[0], b[2]));
    out[2] = hn::Sub(hn::Mul(a[0], b[1]), hn::Mul(a[1], b[0]));
}

using M = hn::Mask<D>;

// A vector of rays' uniforms from ray `ray` on, from their keyed streams; with `digits` and
// `scrambles` (rays/sobol.h's sobol_digits, `stride` apart) finished as sobol_draws does.
HWY_INLINE void ray_uniforms(D d, const std::uint32_t* digits, const std::uint32_t* scrambles,
                             std::size_t stride, std::uint64_t seed, std::uint64_t key,
                             std::uint64_t ray, std::size_t k, V xi[kRayDraws]) {
    const DU du;
    Streams rng(du, seed, key, hn::Iota(du, ray));
    if (digits == nullptr) {
        for (std::size_t j = 0; j < kRayDraws; ++j) xi[j] = rng.uniform(du);
        return;
    }
    const DU32 du32;
    rng.next(du);  // the alias pick's draw, unused: the others keep their places
    xi[0] = hn::Zero(d);
    for (std::size_t j = 0; j < kSequenceDimensions; ++j) {
        const VU32 high = owen_scramble(du32, hn::LoadU(du32, digits + j * stride + k),
                                        hn::LoadU(du32, scrambles + j * stride + k));
        const VU low = hn::ShiftRight<43>(rng.next(du));
        xi[j + 1] = Streams::to_unit(hn::Or(hn::ShiftLeft<21>(hn::PromoteTo(du, high)), low));
    }
    xi[kRayDraws - 1] = rng.uniform(du);
}

// The rays' regions: the ones the strata dealt (`given`, from ray k), or Walker's alias
// table's picks (rays/alias_table.h), bins of {keep, alias}.
HWY_INLINE VI ray_regions(D d, const std::uint32_t* given, std::size_t k,
                          const AliasTable::Bin* bins, std::size_t region_count, V xi_region) {
    const DU du;
    const DI di;
    if (given != nullptr) {
        return hn::BitCast(
            di, hn::PromoteTo(du, hn::LoadU(hn::Rebind<std::uint32_t, DU>(), given + k)));
    }
    const double* const bin_doubles = reinterpret_cast<const double*>(bins);
    const V scaled = hn::Mul(xi_region, hn::Set(d, double(region_count)));
    const VI bin = hn::Min(hn::ConvertTo(di, scaled), hn::Set(di, std::int64_t(region_count) - 1));
    const V keep = hn::GatherIndex(d, bin_doubles, hn::ShiftLeft<1>(bin));
    const VI alias =
        hn::BitCast(di, hn::GatherIndex(du, reinterpret_cast<const std::uint64_t*>(bins),
                                        hn::Add(hn::ShiftLeft<1>(bin), hn::Set(di, 1))));
    return hn::IfThenElse(hn::RebindMask(di, hn::Lt(hn::Sub(scaled, hn::ConvertTo(d, bin)), keep)),
                          bin, alias);
}

// The rays' regions' domains and their patches' corners and normals.
struct RegionGeometry {
    V u0, v0, s;
    V c[4][3], normal[3];
    V out_normal[3];  // the normal of the side the rays leave
    M is_triangle, is_bilinear;
};

// When every lane starts from one region (the usual case when the rays are dealt to their
// sources), its fields are read once and broadcast: the same values the gathers would read.
HWY_INLINE RegionGeometry one_region_geometry(D d, const RayRegion& region, const Patch& patch) {
    RegionGeometry r;
    r.u0 = hn::Set(d, region.u0);
    r.v0 = hn::Set(d, region.v0);
    r.s = hn::Set(d, region.s);
    for (int q = 0; q < 4; ++q) {
        for (int a = 0; a < 3; ++a) r.c[q][a] = hn::Set(d, patch.corner[q][a]);
    }
    const bool back = region.side == kBack;
    for (int a = 0; a < 3; ++a) {
        r.normal[a] = hn::Set(d, patch.normal[a]);
        r.out_normal[a] = back ? hn::Neg(r.normal[a]) : r.normal[a];
    }
    const auto every_lane_if = [&](bool yes) { return hn::FirstN(d, yes ? hn::Lanes(d) : 0); };
    r.is_triangle = every_lane_if(region.map == RegionMap::triangle);
    r.is_bilinear = every_lane_if(region.map == RegionMap::bilinear);
    return r;
}

HWY_INLINE RegionGeometry region_geometry(D d, VI region, const RayRegion* regions,
                                          const Patch* patches, const rg::PatchLayout& layout) {
    const DU du;
    const DI di;
    const std::int64_t first = hn::GetLane(region);
    if (hn::AllTrue(di, hn::Eq(region, hn::Set(di, first)))) {
        const RayRegion& one = regions[first];
        return one_region_geometry(d, one, patches[one.patch]);
    }
    const double* const patch_doubles = reinterpret_cast<const double*>(patches);
    const double* const region_doubles = reinterpret_cast<const double*>(regions);
    RegionGeometry r;
    const VI at = hn::ShiftLeft<2>(region);
    r.u0 = hn::GatherIndex(d, region_doubles, at);
    r.v0 = hn::GatherIndex(d, region_doubles, hn::Add(at, hn::Set(di, 1)));
    r.s = hn::GatherIndex(d, region_doubles, hn::Add(at, hn::Set(di, 2)));
    const VI patch_map =
        hn::BitCast(di, hn::GatherIndex(du, reinterpret_cast<const std::uint64_t*>(regions),
                                        hn::Add(at, hn::Set(di, 3))));
    const VI patch = hn::And(patch_map, hn::Set(di, 0xffffffff));
    const VI map = hn::And(hn::ShiftRight<32>(patch_map), hn::Set(di, 0xffff));
    const auto back = hn::RebindMask(d, hn::Eq(hn::ShiftRight<48>(patch_map), hn::Set(di, 1)));
    const VI base =
        hn::BitCast(di, hn::Mul(hn::BitCast(du, patch), hn::Set(du, std::uint64_t(layout.stride))));
    for (int q = 0; q < 4; ++q) {
        for (int a = 0; a < 3; ++a) {
            r.c[q][a] = hn::GatherIndex(d, patch_doubles,
                                        hn::Add(base, hn::Set(di, layout.corner + 3 * q + a)));
        }
    }
    for (int a = 0; a < 3; ++a) {
        r.normal[a] =
            hn::GatherIndex(d, patch_doubles, hn::Add(base, hn::Set(di, layout.normal + a)));
    }
    // The corners' map is the same on either side; the direction leaves the region's side.
    for (int a = 0; a < 3; ++a)
        r.out_normal[a] = hn::IfThenElse(back, hn::Neg(r.normal[a]), r.normal[a]);
    r.is_triangle = hn::RebindMask(d, hn::Eq(map, hn::Set(di, 0)));
    r.is_bilinear = hn::RebindMask(d, hn::Eq(map, hn::Set(di, 2)));
    return r;
}

// The point, uniform by area on the region (rays/element_sampler.h): its parameters u, v and
// its position.
HWY_INLINE void sample_point(D d, const RegionGeometry& r, V xi_u, V xi_v, V& u, V& v,
                             V origin[3]) {
    const V one = hn::Set(d, 1.0);
    // P(u, v) = c0 + u e1 + v ev + u v g: ev = c2 - c0, g = 0 on a triangle; ev = c3 - c0,
    // g = (c0 - c1) + (c2 - c3) on a quad.
    V e1[3], ev[3], g[3];
    for (int a = 0; a < 3; ++a) {
        e1[a] = hn::Sub(r.c[1][a], r.c[0][a]);
        ev[a] = hn::IfThenElse(r.is_triangle, hn::Sub(r.c[2][a], r.c[0][a]),
                               hn::Sub(r.c[3][a], r.c[0][a]));
        g[a] = hn::IfThenElseZero(hn::Not(r.is_triangle), hn::Add(hn::Sub(r.c[0][a], r.c[1][a]),
                                                                  hn::Sub(r.c[2][a], r.c[3][a])));
    }
    const V root = hn::Sqrt(xi_u);
    const V tri_a = hn::Mul(root, hn::Sub(one, xi_v)), tri_b = hn::Mul(root, xi_v);
    V a = hn::IfThenElse(r.is_triangle, tri_a, xi_u);
    V b = hn::IfThenElse(r.is_triangle, tri_b, xi_v);
    if (!hn::AllFalse(d, r.is_bilinear)) {
        // The Jacobian n . (dP/du x dP/dv) = k0 + k1 u + k2 v, at the domain's corners.
        V x[3];
        cross3(e1, ev, x);
        const V k0 = dot3(r.normal, x);
        cross3(e1, g, x);
        const V k1 = dot3(r.normal, x);
        cross3(g, ev, x);
        const V k2 = dot3(r.normal, x);
        const V u0 = r.u0, v0 = r.v0;
        const V u1 = hn::Add(u0, r.s), v1 = hn::Add(v0, r.s);
        const V j00 = hn::Add(hn::Add(k0, hn::Mul(k1, u0)), hn::Mul(k2, v0));
        const V j10 = hn::Add(hn::Add(k0, hn::Mul(k1, u1)), hn::Mul(k2, v0));
        const V j11 = hn::Add(hn::Add(k0, hn::Mul(k1, u1)), hn::Mul(k2, v1));
        const V j01 = hn::Add(hn::Add(k0, hn::Mul(k1, u0)), hn::Mul(k2, v1));
        const V bs = linear(d, hn::Add(j00, j01), hn::Add(j10, j11), xi_u);
        const V ns = hn::Sub(one, bs);
        const V bt = linear(d, hn::Add(hn::Mul(ns, j00), hn::Mul(bs, j10)),
                            hn::Add(hn::Mul(ns, j01), hn::Mul(bs, j11)), xi_v);
        a = hn::IfThenElse(r.is_bilinear, bs, a);
        b = hn::IfThenElse(r.is_bilinear, bt, b);
    }
    u = hn::Add(r.u0, hn::Mul(r.s, a));
    v = hn::Add(r.v0, hn::Mul(r.s, b));
    const V uv = hn::Mul(u, v);
    for (int k3 = 0; k3 < 3; ++k3) {
        origin[k3] = hn::Add(hn::Add(hn::Add(r.c[0][k3], hn::Mul(u, e1[k3])), hn::Mul(v, ev[k3])),
                             hn::Mul(uv, g[k3]));
    }
}

// The direction: r cos(phi) t + r sin(phi) b + sqrt(1 - r^2) n, in the tangent frame of
// Duff et al. 2017 (rays/sampling.h) about the outward normal n.
HWY_INLINE void sample_direction(D d, const V n[3], V xi_r, V xi_phi, V dir[3]) {
    const V one = hn::Set(d, 1.0), zero = hn::Zero(d);
    const V sign = hn::CopySign(one, n[2]);
    const V fa = hn::Div(hn::Set(d, -1.0), hn::Add(sign, n[2]));
    const V fc = hn::Mul(hn::Mul(n[0], n[1]), fa);
    const V t[3] = {hn::Add(one, hn::Mul(hn::Mul(hn::Mul(sign, n[0]), n[0]), fa)),
                    hn::Mul(sign, fc), hn::Neg(hn::Mul(sign, n[0]))};
    const V bt3[3] = {fc, hn::Add(sign, hn::Mul(hn::Mul(n[1], n[1]), fa)), hn::Neg(n[1])};
    const V r = hn::Sqrt(xi_r);
    V cos_phi, sin_phi;
    cos_sin_turn(d, xi_phi, cos_phi, sin_phi);
    const V rc = hn::Mul(r, cos_phi), rs = hn::Mul(r, sin_phi);
    const V z = hn::Sqrt(hn::Max(zero, hn::Sub(one, xi_r)));
    for (int k3 = 0; k3 < 3; ++k3) {
        dir[k3] = hn::Add(hn::Add(hn::Mul(rc, t[k3]), hn::Mul(rs, bt3[k3])), hn::Mul(z, n[k3]));
    }
}

// A vector of rays stored at o, the doubles rounded to floats: `count` of them, all when
// count is a whole vector, else lane by lane.
HWY_INLINE void store_rays(D d, const V origin[3], const V dir[3], V u, V v, V dither, VI region,
                           std::size_t count, std::size_t o, GeneratedRays* out) {
    const DU du;
    if (count >= hn::Lanes(d)) {
        const hn::Rebind<float, D> df;
        const hn::Rebind<std::uint32_t, DU> du32;
        for (int k3 = 0; k3 < 3; ++k3) {
            hn::StoreU(hn::DemoteTo(df, origin[k3]), df, out->origin[k3].data() + o);
            hn::StoreU(hn::DemoteTo(df, dir[k3]), df, out->direction[k3].data() + o);
        }
        hn::StoreU(hn::DemoteTo(df, u), df, out->u.data() + o);
        hn::StoreU(hn::DemoteTo(df, v), df, out->v.data() + o);
        hn::StoreU(dither, d, out->dither.data() + o);
        hn::StoreU(hn::TruncateTo(du32, hn::BitCast(du, region)), du32, out->region.data() + o);
        return;
    }
    HWY_ALIGN double lane_doubles[9][HWY_LANES(double)];
    HWY_ALIGN std::uint64_t lane_region[HWY_LANES(double)];
    for (int k3 = 0; k3 < 3; ++k3) {
        hn::Store(origin[k3], d, lane_doubles[k3]);
        hn::Store(dir[k3], d, lane_doubles[3 + k3]);
    }
    hn::Store(u, d, lane_doubles[6]);
    hn::Store(v, d, lane_doubles[7]);
    hn::Store(dither, d, lane_doubles[8]);
    hn::Store(hn::BitCast(du, region), du, lane_region);
    for (std::size_t l = 0; l < count; ++l) {
        for (int k3 = 0; k3 < 3; ++k3) {
            out->origin[k3][o + l] = float(lane_doubles[k3][l]);
            out->direction[k3][o + l] = float(lane_doubles[3 + k3][l]);
        }
        out->u[o + l] = float(lane_doubles[6][l]);
        out->v[o + l] = float(lane_doubles[7][l]);
        out->dither[o + l] = lane_doubles[8][l];
        out->region[o + l] = std::uint32_t(lane_region[l]);
    }
}

// `digits` and `scrambles`, when given, hold every ray's Sobol digits and their scrambles
// (rays/sobol.h's sobol_digits, `stride` apart and readable a whole vector past n); otherwise
// the uniforms come from the rays' keyed streams alone. `given`, when given, holds every ray's
// region (as readable), which the alias table otherwise picks.
void GenerateRays(const Patch* patches, const RayRegion* regions, std::size_t region_count,
                  const AliasTable::Bin* bins, std::uint64_t seed, std::uint64_t key,
                  std::uint64_t first, std::size_t n, const std::uint32_t* digits,
                  const std::uint32_t* scrambles, std::size_t stride, const std::uint32_t* given,
                  GeneratedRays* out, std::size_t offset) {
    const D d;
    const std::size_t lanes = hn::Lanes(d);
    const rg::PatchLayout layout = rg::patch_layout();
    for (std::size_t k = 0; k < n; k += lanes) {
        V xi[kRayDraws];
        ray_uniforms(d, digits, scrambles, stride, seed, key, first + k, k, xi);
        const V xi_region = xi[0], xi_u = xi[1], xi_v = xi[2], xi_r = xi[3], xi_phi = xi[4];
        const V dither = xi[5];
        const VI region = ray_regions(d, given, k, bins, region_count, xi_region);
        const RegionGeometry geometry = region_geometry(d, region, regions, patches, layout);
        V u, v, origin[3], dir[3];
        sample_point(d, geometry, xi_u, xi_v, u, v, origin);
        sample_direction(d, geometry.out_normal, xi_r, xi_phi, dir);
        store_rays(d, origin, dir, u, v, dither, region, n - k, offset + k, out);
    }
}

}  // namespace hmcr::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace hmcr {

HWY_EXPORT(GenerateRays);

RegionMap region_map(const Patch& patch) {
    if (!patch.is_quad()) return RegionMap::triangle;
    return patch.is_parallelogram() ? RegionMap::parallelogram : RegionMap::bilinear;
}

void GeneratedRays::resize(std::size_t n) {
    for (int k = 0; k < 3; ++k) {
        resize_populated(origin[k], n);
        resize_populated(direction[k], n);
    }
    resize_populated(region, n);
    resize_populated(u, n);
    resize_populated(v, n);
    resize_populated(dither, n);
}

RayStartSample scalar_ray(const std::vector<Patch>& patches, std::span<const RayRegion> regions,
                          const AliasTable& table, std::uint64_t seed, std::uint64_t key,
                          std::uint64_t index, RaySequence sequence, const RayStrata* strata) {
    double xi[kRayDraws];
    std::uint32_t source = 0;
    const bool sobol = sequence == RaySequence::sobol;
    if (sobol) {
        sobol_draws(seed, key, *strata, index, 1, xi, 1, &source);
    } else {
        Rng rng(seed, key, index);
        for (double& x : xi) x = rng.uniform();
    }
    const double xi_region = xi[0], xi_u = xi[1], xi_v = xi[2], xi_r = xi[3], xi_phi = xi[4];
    RayStartSample out;
    out.dither = xi[5];
    out.region = sobol ? source : std::uint32_t(table.sample(xi_region));
    const RayRegion& reg = regions[out.region];
    const Patch& p = patches[reg.patch];
    const bool triangle = reg.map == RegionMap::triangle;
    const Vec3 facing = reg.side == kBack ? Vec3(-p.normal) : p.normal;
    Vec3 e1, ev, g;
    for (int a = 0; a < 3; ++a) {
        e1[a] = p.corner[1][a] - p.corner[0][a];
        ev[a] = triangle ? p.corner[2][a] - p.corner[0][a] : p.corner[3][a] - p.corner[0][a];
        g[a] =
            triangle ? 0.0 : (p.corner[0][a] - p.corner[1][a]) + (p.corner[2][a] - p.corner[3][a]);
    }
    const auto cross = [](const Vec3& x, const Vec3& y) {
        return Vec3(x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                    x[0] * y[1] - x[1] * y[0]);
    };
    const auto dot = [](const Vec3& x, const Vec3& y) {
        return (x[0] * y[0] + x[1] * y[1]) + x[2] * y[2];
    };
    double a = xi_u, b = xi_v;
    if (triangle) {
        const Vec2 ab = sample_uniform_triangle(xi_u, xi_v);
        a = ab.x();
        b = ab.y();
    } else if (reg.map == RegionMap::bilinear) {
        const Vec3& n = p.normal;
        const double k0 = dot(n, cross(e1, ev)), k1 = dot(n, cross(e1, g)),
                     k2 = dot(n, cross(g, ev));
        const double u1 = reg.u0 + reg.s, v1 = reg.v0 + reg.s;
        const double j00 = (k0 + k1 * reg.u0) + k2 * reg.v0, j10 = (k0 + k1 * u1) + k2 * reg.v0;
        const double j11 = (k0 + k1 * u1) + k2 * v1, j01 = (k0 + k1 * reg.u0) + k2 * v1;
        a = sample_linear(j00 + j01, j10 + j11, xi_u);
        const double na = 1.0 - a;
        b = sample_linear(na * j00 + a * j10, na * j01 + a * j11, xi_v);
    }
    const double u = reg.u0 + reg.s * a, v = reg.v0 + reg.s * b, uv = u * v;
    out.uv = {u, v};
    for (int k = 0; k < 3; ++k) {
        out.origin[k] = ((p.corner[0][k] + u * e1[k]) + v * ev[k]) + uv * g[k];
    }
    const Vec3& n = facing;
    Vec3 t, bt;
    tangent_frame(n, t, bt);
    double cos_phi = 0, sin_phi = 0;
    cos_sin_turn(xi_phi, cos_phi, sin_phi);
    const double r = std::sqrt(xi_r);
    const double rc = r * cos_phi, rs = r * sin_phi;
    const double z = std::sqrt(std::max(0.0, 1.0 - xi_r));
    for (int k = 0; k < 3; ++k) out.direction[k] = (rc * t[k] + rs * bt[k]) + z * n[k];
    return out;
}

void generate_rays(const std::vector<Patch>& patches, std::span<const RayRegion> regions,
                   const AliasTable& table, std::uint64_t seed, std::uint64_t key,
                   std::uint64_t first, std::size_t n, GeneratedRays& out, std::size_t offset,
                   RaySequence sequence, const RayStrata* strata) {
    const std::uint32_t* digits = nullptr;
    const std::uint32_t* scrambles = nullptr;
    const std::uint32_t* given = nullptr;
    // Padded by more lanes than the widest vector of any target has, so that the last rays'
    // loads stay inside (HWY_MAX_BYTES, here outside the targets' code, is the last target's).
    constexpr std::size_t kPadding = 64;
    const std::size_t stride = n + kPadding;
    if (sequence == RaySequence::sobol) {
        thread_local std::vector<std::uint32_t> digit_buffer, scramble_buffer, sources;
        resize_populated(digit_buffer, kSequenceDimensions * stride);
        resize_populated(scramble_buffer, kSequenceDimensions * stride);
        resize_populated(sources, stride);
        sobol_digits(seed, key, *strata, first, n, digit_buffer.data(), scramble_buffer.data(),
                     stride, sources.data());
        // The padding is read too: digits and the first source, so that its gathers stay
        // inside.
        for (std::size_t d = 0; d < kSequenceDimensions; ++d) {
            for (auto* buffer : {&digit_buffer, &scramble_buffer}) {
                std::fill(buffer->begin() + std::ptrdiff_t(d * stride + n),
                          buffer->begin() + std::ptrdiff_t((d + 1) * stride), 0u);
            }
        }
        std::fill(sources.begin() + std::ptrdiff_t(n), sources.end(), 0);
        digits = digit_buffer.data();
        scrambles = scramble_buffer.data();
        given = sources.data();
    }
    HWY_DYNAMIC_DISPATCH(GenerateRays)
    (patches.data(), regions.data(), regions.size(), table.bins(), seed, key, first, n, digits,
     scrambles, stride, given, &out, offset);
}

}  // namespace hmcr
#endif  // HWY_ONCE
