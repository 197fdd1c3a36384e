// SPDX-License-Identifier: Apache-2.0
// The sequences a fixed mesh's leaves keep through a pass (radiosity/sequence_cursors.h): each
// leaf keeps its sequence whatever its place among an iteration's sources, and even when a back
// side is made between iterations, and starts each iteration at the point after the rays the
// strata dealt it before.
#include "radiosity/sequence_cursors.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

RayRegion region_of(const Hierarchy& h, const Element& e) {
    return {e.domain.u0,
            e.domain.v0,
            e.domain.s,
            e.id.patch,
            region_map(h.patch_set().patches[e.id.patch]),
            e.id.side};
}

TEST(SequenceCursors, ALeafKeepsItsSequenceAndGoesOnFromItsLastPoint) {
    std::vector<TestPolygon> polygons = {
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, Rgb::Constant(0.5), Rgb::Zero()},
        {{{5, 0, 0}, {7, 0.5, 0}, {5.5, 2, 0}}, Rgb::Constant(0.5), Rgb::Constant(1)}};
    for (TestPolygon& p : polygons) p.two_sided = true;
    Hierarchy h(build_patch_set(make_patch_mesh(polygons)), {});
    h.subdivide(h.subdivide(h.root(0))[2]);
    h.subdivide(h.root(1));  // a triangle's middle child has an inverted domain
    h.root(0, kBack);        // patch 1's back is made only between the iterations below
    const LeafIndex index(h);
    constexpr std::uint64_t kKey = (std::uint64_t(1) << 32) + 5;
    SequenceCursors cursors(index, kKey);
    std::vector<const Element*> leaves;
    h.for_each_leaf([&](const Element& e) { leaves.push_back(&e); });
    ASSERT_EQ(leaves.size(), 12u);  // 7 + 4 fronts, 1 back
    // Three iterations over leaves that come, go and change places, the last one with the back
    // of patch 1, made since the index was.
    const std::vector<std::vector<std::size_t>> picks{{0, 3, 7, 11}, {11, 0, 8, 3, 1}, {}};
    std::map<const Element*, std::uint64_t> next;
    std::map<const Element*, std::uint64_t> sequence_of;
    for (std::size_t t = 0; t < 3; ++t) {
        std::vector<const Element*> sources;
        for (const std::size_t k : picks[t]) sources.push_back(leaves[k]);
        if (t == 2) sources = {&h.root(1, kBack), leaves[3], leaves[8], leaves[0]};
        std::vector<RayRegion> regions;
        std::vector<double> weights;
        for (const Element* e : sources) {
            regions.push_back(region_of(h, *e));
            weights.push_back(1.0 + double(regions.size()));
        }
        RayStrata strata;
        strata.assign(weights, 1000 + 37 * t, 0.4, 5000 * t);
        cursors.advance(regions, strata);
        ASSERT_TRUE(strata.continued());
        EXPECT_EQ(strata.scramble_key(t), kKey);
        for (std::uint32_t l = 0; l < strata.sources(); ++l) {
            const Element* e = sources[l];
            const auto known = sequence_of.try_emplace(e, strata.sequence(l)).first;
            EXPECT_EQ(strata.sequence(l), known->second) << "iteration " << t << ", source " << l;
            EXPECT_EQ(strata.first_point(l), next[e]) << "iteration " << t << ", source " << l;
            next[e] += strata.first_ray(l + 1) - strata.first_ray(l);
        }
    }
    std::set<std::uint64_t> distinct;
    for (const auto& [e, s] : sequence_of) distinct.insert(s);
    EXPECT_EQ(distinct.size(), sequence_of.size());  // one sequence a leaf
    EXPECT_EQ(sequence_of.size(), 7u);
}

}  // namespace
}  // namespace hmcr::test
