// SPDX-License-Identifier: Apache-2.0
// The vector ray generator: the same bits as its one-lane reference on every instruction set
// the machine runs, and the densities it promises (docs/design.md §3.1): regions by weight,
// points uniform by area, directions cosine-distributed.
#include "rays/ray_generator.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

#include "rays/domain.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// A planar skewed quad (bilinear), a parallelogram, a triangle, and a quad facing down (the tangent
// frame's other sign), each split into regions of several sizes.
struct Regions {
    PatchSet set;
    std::vector<RayRegion> regions;
    std::vector<double> weights;
};

Regions test_regions() {
    const TestPolygon skewed{
        {{0, 0, 0}, {3, 0, 0}, {2.2, 1.0, 0.3}, {0.1, 2.5, 0.75}}, Rgb::Constant(0.5), Rgb::Zero()};
    const TestPolygon parallelogram{
        {{4, 0, 0}, {6, 0, 1}, {7, 2, 1}, {5, 2, 0}}, Rgb::Constant(0.5), Rgb::Zero()};
    const TestPolygon triangle{
        {{4, 0, 3}, {6, 0.5, 3}, {4.5, 2, 3.5}}, Rgb::Constant(0.5), Rgb::Zero()};
    const TestPolygon down{
        {{0, 0, 5}, {0, 2, 5}, {2, 2, 5}, {2, 0, 5}}, Rgb::Constant(0.5), Rgb::Zero()};
    Regions r;
    r.set = build_patch_set(make_patch_mesh({skewed, parallelogram, triangle, down}));
    const Domain whole = Domain::root();
    for (std::uint32_t p = 0; p < r.set.patches.size(); ++p) {
        const Patch& patch = r.set.patches[p];
        for (const Domain& dom : {whole, whole.child(patch.is_quad(), 3),
                                  whole.child(patch.is_quad(), 1).child(patch.is_quad(), 2)}) {
            r.regions.push_back({dom.u0, dom.v0, dom.s, p, region_map(patch)});
            r.weights.push_back(1.0 + double(r.regions.size() % 5));
        }
    }
    return r;
}

constexpr std::size_t kRays = 20'000;

// n rays of the stream (seed, key) from the regions, by their weights.
GeneratedRays generated(const Regions& r, std::uint64_t seed, std::uint64_t key, std::size_t n) {
    const AliasTable table(r.weights);
    GeneratedRays out;
    out.resize(n);
    generate_rays(r.set.patches, r.regions, table, seed, key, 0, n, out, 0, RaySequence::random,
                  nullptr);
    return out;
}

void expect_equal_to_reference(const Regions& r, const AliasTable& table, const char* target,
                               RaySequence sequence, const RayStrata* strata) {
    GeneratedRays out;
    out.resize(kRays + 3);
    // An odd count at an offset: the last vector is partial.
    generate_rays(r.set.patches, r.regions, table, 7, 11, 1000, kRays, out, 3, sequence, strata);
    for (std::size_t k = 0; k < kRays; ++k) {
        const RayStartSample s =
            scalar_ray(r.set.patches, r.regions, table, 7, 11, 1000 + k, sequence, strata);
        const std::size_t o = k + 3;
        ASSERT_EQ(out.region[o], s.region) << target << " ray " << k;
        ASSERT_EQ(out.u[o], float(s.uv.x())) << target << " ray " << k;
        ASSERT_EQ(out.v[o], float(s.uv.y())) << target << " ray " << k;
        ASSERT_EQ(out.dither[o], s.dither) << target << " ray " << k;
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(out.origin[c][o], float(s.origin[c])) << target << " ray " << k;
            ASSERT_EQ(out.direction[c][o], float(s.direction[c])) << target << " ray " << k;
        }
    }
}

TEST(RayGenerator, EveryInstructionSetGivesTheReferenceBits) {
    const Regions r = test_regions();
    const AliasTable table(r.weights);
    RayStrata strata;
    strata.assign(r.weights, kRays, 0.375, 1000);
    // Sequences continued from points of every size, the origin's among them.
    RayStrata continued = strata;
    continued.continue_sequences(5);
    for (std::uint32_t l = 0; l < continued.sources(); ++l) {
        continued.continue_source(l, 3 * l + 1, l == 2 ? 0 : (std::uint64_t(1) << (3 * l)) - 1);
    }
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        expect_equal_to_reference(r, table, hwy::TargetName(target), RaySequence::random, nullptr);
        for (const RayStrata* s : {&strata, &continued}) {
            expect_equal_to_reference(r, table, hwy::TargetName(target), RaySequence::sobol, s);
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

// A region is picked with its weight's share; within it, a point lands in each child of its
// domain with the child's share of the area.
TEST(RayGenerator, RegionsByWeightAndPointsUniformByArea) {
    const Regions r = test_regions();
    const std::size_t n = 400'000;
    const GeneratedRays out = generated(r, 3, 5, n);
    const double total = std::accumulate(r.weights.begin(), r.weights.end(), 0.0);
    std::vector<std::array<int, 4>> children(r.regions.size());
    std::vector<int> picked(r.regions.size());
    for (std::size_t k = 0; k < n; ++k) {
        const RayRegion& reg = r.regions[out.region[k]];
        const Domain dom{float(reg.u0), float(reg.v0), float(reg.s)};
        const bool quad = r.set.patches[reg.patch].is_quad();
        ++picked[out.region[k]];
        ++children[out.region[k]][dom.child_containing(quad, Vec2(out.u[k], out.v[k]))];
    }
    for (std::size_t i = 0; i < r.regions.size(); ++i) {
        const double p = r.weights[i] / total;
        EXPECT_TRUE(within_standard_errors("region " + std::to_string(i), picked[i] / double(n), p,
                                           std::sqrt(p * (1 - p) / double(n))));
        const RayRegion& reg = r.regions[i];
        const Patch& patch = r.set.patches[reg.patch];
        const Domain dom{float(reg.u0), float(reg.v0), float(reg.s)};
        double area = 0;
        std::array<double, 4> child_area{};
        for (int c = 0; c < 4; ++c) {
            const auto uv = dom.child(patch.is_quad(), c).corners(patch.is_quad());
            child_area[c] = patch.region_area(uv.data(), patch.corner_count);
            area += child_area[c];
        }
        for (int c = 0; c < 4; ++c) {
            const double q = child_area[c] / area, m = picked[i];
            EXPECT_TRUE(within_standard_errors(
                "region " + std::to_string(i) + " child " + std::to_string(c), children[i][c] / m,
                q, std::sqrt(q * (1 - q) / m)));
        }
    }
}

// Cosine-distributed: cos^2(theta) is uniform on [0, 1], and the azimuth uniform; each
// direction is a unit vector on the patch's front side.
TEST(RayGenerator, DirectionsAreCosineDistributed) {
    const Regions r = test_regions();
    const std::size_t n = 400'000;
    const GeneratedRays out = generated(r, 9, 2, n);
    constexpr int kBins = 8;
    std::array<int, kBins> cos2_bins{}, azimuth_bins{};
    for (std::size_t k = 0; k < n; ++k) {
        const Patch& patch = r.set.patches[r.regions[out.region[k]].patch];
        const Vec3 d(out.direction[0][k], out.direction[1][k], out.direction[2][k]);
        ASSERT_NEAR(d.norm(), 1.0, 1e-6);
        const double cos_theta = d.dot(patch.normal);
        ASSERT_GT(cos_theta, -1e-6);
        ++cos2_bins[std::min(kBins - 1, int(cos_theta * cos_theta * kBins))];
        // The azimuth around the normal, from the patch's first edge.
        const Vec3 x = (patch.corner[1] - patch.corner[0]).normalized();
        const Vec3 y = patch.normal.cross(x);
        const double phi = std::atan2(d.dot(y), d.dot(x)) + std::numbers::pi;
        ++azimuth_bins[std::min(kBins - 1, int(phi / (2 * std::numbers::pi) * kBins))];
    }
    const double p = 1.0 / kBins, se = std::sqrt(p * (1 - p) / double(n));
    for (int b = 0; b < kBins; ++b) {
        EXPECT_TRUE(within_standard_errors("cos^2 bin " + std::to_string(b),
                                           cos2_bins[b] / double(n), p, se));
        EXPECT_TRUE(within_standard_errors("azimuth bin " + std::to_string(b),
                                           azimuth_bins[b] / double(n), p, se));
    }
}

}  // namespace
}  // namespace hmcr::test
