// SPDX-License-Identifier: Apache-2.0
#include "rays/triangle_patches.h"

#include <gtest/gtest.h>

#include <vector>

#include "rays/rng.h"

namespace hmcr::test {
namespace {

// Triangles and quads in a random order, across many 64-triangle words: every triangle names
// the patch it was pushed for.
TEST(TrianglePatches, EveryTriangleNamesItsPatch) {
    Rng rng(20261125, 0);
    TrianglePatches map;
    std::vector<std::uint32_t> expected;
    for (std::uint32_t patch = 0; patch < 5'000; ++patch) {
        const bool quad = rng.uniform() < 0.7;
        map.push(false);
        expected.push_back(patch);
        if (quad) {
            map.push(true);
            expected.push_back(patch);
        }
    }
    ASSERT_EQ(map.size(), expected.size());
    for (std::uint32_t t = 0; t < expected.size(); ++t) EXPECT_EQ(map[t], expected[t]) << t;
}

TEST(TrianglePatches, AllQuadsAndAllTriangles) {
    TrianglePatches quads, triangles;
    for (int i = 0; i < 200; ++i) {
        quads.push(false);
        quads.push(true);
        triangles.push(false);
    }
    for (std::uint32_t t = 0; t < 400; ++t) EXPECT_EQ(quads[t], t / 2);
    for (std::uint32_t t = 0; t < 200; ++t) EXPECT_EQ(triangles[t], t);
}

}  // namespace
}  // namespace hmcr::test
