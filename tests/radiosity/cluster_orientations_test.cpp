// SPDX-License-Identifier: Apache-2.0
// Oriented clusters' orientation classes (docs/design.md §2.7): sides grouped by the direction
// they face, a ray's power split among the classes that face it by their projected areas (whole
// quanta, summing to the ray's), and each class's irradiance carried down to its sides.
#include "radiosity/cluster_orientations.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "radiosity/clusters.h"
#include "rays/rng.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

using Child = ClusterOrientations::Child;

Child side(std::uint32_t value, double area, const Vec3& normal) {
    return {false, value, area, normal};
}
Child cluster(std::uint32_t index) { return {true, index, 0, {}}; }

TEST(ClusterOrientations, NearbyNormalsShareABinAndOppositeOnesDoNot) {
    using O = ClusterOrientations;
    for (const Vec3& n : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(-1, 0, 0),
                          Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0.3, -0.5, 0.81).normalized()}) {
        EXPECT_LT(O::bin(n), O::kBins);
        EXPECT_NE(O::bin(n), O::bin(-n));
        EXPECT_EQ(O::bin(n), O::bin(n * 2.5));  // a direction's, whatever its length
    }
    std::set<std::uint16_t> seen;
    Rng rng(1, 2);
    for (int k = 0; k < 200'000; ++k) {
        const double z = 2 * rng.uniform() - 1, phi = 2 * std::numbers::pi * rng.uniform();
        const double r = std::sqrt(1 - z * z);
        seen.insert(O::bin({r * std::cos(phi), r * std::sin(phi), z}));
    }
    EXPECT_EQ(seen.size(), O::kBins);  // every bin is reached
}

// Two sides facing +z (area 2) and +x (area 1) under one cluster, a third facing +z under
// another, joined by a parent: classes merge by bin, and a deposit splits by projected area.
class TwoClasses : public testing::Test {
protected:
    TwoClasses() : o(2, 8) {
        o.add_cluster(1, side(0, 2, {0, 0, 1}), side(2, 1, {1, 0, 0}));
        o.add_cluster(0, cluster(1), side(4, 3, {0, 0, 1}));
    }
    ClusterOrientations o;
};

TEST_F(TwoClasses, ClassesMergeByBin) {
    EXPECT_EQ(o.classes_of(1), 2u);
    EXPECT_EQ(o.classes_of(0), 2u);  // +z (areas 2 + 3) and +x
    EXPECT_EQ(o.classes(), 4u);
    // Toward +z the +z sides project their whole area, the +x side none: 5 of 6.
    EXPECT_DOUBLE_EQ(o.projected_fraction(0, {0, 0, 1}), 5.0 / 6.0);
    EXPECT_DOUBLE_EQ(o.projected_fraction(1, Vec3(1, 0, 1).normalized()), 3 * std::sqrt(0.5) / 3);
}

// Straight down, all of the ray's power goes to the +z class; at 45 degrees between -x and -z,
// 2 / 3 to +z and 1 / 3 to +x, in whole quanta summing to the ray's, unbiased over the
// roundings: the mean share is within 4 standard errors of the rounding's (a uniform's,
// at most 1/2 quantum per ray) of 2 q / 3.
TEST_F(TwoClasses, ADepositGoesToTheClassesFacingTheRayByTheirProjectedArea) {
    const Quanta q{1000, 7, -5};
    o.deposit(1, {0, 0, -1}, q, 0.25);
    const std::span<Quanta> received = o.received();
    Quanta total{};
    for (const Quanta& r : received) add(total, r);
    EXPECT_EQ(total, q);
    const std::size_t z_class = received[0] == q ? 0 : 1;
    EXPECT_EQ(received[z_class], q);

    for (Quanta& r : received) r = {};
    const int rays = 10'000;
    Rng rng(3, 4);
    for (int k = 0; k < rays; ++k) {
        o.deposit(1, Vec3(-1, 0, -1).normalized(), q, rng.uniform());
        Quanta sum{};
        for (const Quanta& r : received) add(sum, r);
        ASSERT_EQ(sum[0], std::int64_t(k + 1) * q[0]);
        ASSERT_EQ(sum[2], std::int64_t(k + 1) * q[2]);
    }
    const double mean_z = double(received[z_class][0]) / rays;
    EXPECT_NEAR(mean_z, 2.0 / 3.0 * 1000, 4 * 0.5 / std::sqrt(double(rays)));
    EXPECT_NEAR(double(received[z_class][1]) / rays, 2.0 / 3.0 * 7, 4 * 0.5 / std::sqrt(rays));
}

// A cluster none of whose classes faces the ray (from below, the sides all face up or +x) takes
// it by area: 2 : 1.
TEST_F(TwoClasses, ARayNoClassFacesIsSplitByArea) {
    const Quanta q{3000, 0, 0};
    o.deposit(1, {0, 0, 1}, q, 0.5);
    const std::span<Quanta> received = o.received();
    const std::int64_t a = received[0][0], b = received[1][0];
    EXPECT_EQ(a + b, 3000);
    EXPECT_EQ(std::max(a, b), 2000);
}

// Push: each side gets its class's received power over the class's area, plus its parent
// class's: the +z sides under cluster 1 hold cluster 1's +z irradiance and cluster 0's.
TEST_F(TwoClasses, PushCarriesEachClassDownToItsSides) {
    const PowerQuantum quantum{Rgb::Constant(0.5)};
    o.deposit(1, {0, 0, -1}, {20, 20, 20}, 0.5);        // 10 W on cluster 1's +z (2 m^2)
    o.deposit(0, {0, 0, -1}, {100, 100, 100}, 0.5);     // 50 W on cluster 0's +z (5 m^2)
    o.deposit(0, {-1, 0, 0}, {6, 6, 6}, 0.5);           // 3 W on cluster 0's +x (1 m^2)
    std::vector<Rgb> irradiance(8, Rgb::Constant(-1));  // -1: left as it was
    o.push(quantum, irradiance);
    EXPECT_DOUBLE_EQ(irradiance[0][0], 10.0 / 2 + 50.0 / 5);
    EXPECT_DOUBLE_EQ(irradiance[2][0], 3.0);
    EXPECT_DOUBLE_EQ(irradiance[4][0], 50.0 / 5);
    EXPECT_EQ(irradiance[1][0], -1);
    for (const Quanta& r : o.received()) EXPECT_EQ(r, Quanta{});
}

// A tree's classes: over an inward box every cluster holds at most one class per wall, and the
// top's are the six walls, each with its wall's area.
TEST(ClusterOrientations, AClusterTreeOverABoxHasOneClassPerWall) {
    Hierarchy h(build_patch_set(make_patch_mesh(
                    inward_box({0, 0, 0}, {1, 2, 3}, 4, Rgb::Constant(0.5), Rgb::Zero()))),
                {});
    ClusterTree tree(h, {}, Clustering::oriented);
    EXPECT_EQ(tree.model(), Clustering::oriented);
    const Element& top = tree.top();
    EXPECT_NEAR(tree.end_cosine(top, {0, 0, 1}), 2.0 / top.area, 1e-12);  // the floor, 1 x 2
    EXPECT_NEAR(tree.end_cosine(top, Vec3(1, 1, 0).normalized()),
                (6 + 3) * std::sqrt(0.5) / top.area, 1e-12);
    EXPECT_FALSE(tree.class_received().empty());
    ClusterTree isotropic(h);
    EXPECT_EQ(isotropic.model(), Clustering::isotropic);
    EXPECT_EQ(isotropic.end_cosine(isotropic.top(), {0, 0, 1}), 0.25);
    EXPECT_TRUE(isotropic.class_received().empty());
}

}  // namespace
}  // namespace hmcr::test
