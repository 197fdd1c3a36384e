// SPDX-License-Identifier: Apache-2.0
// The output of a real solve: a refined furnace whose faces are 2 x 2 coplanar patches, so
// element boundaries meet inside patches, across coplanar patches and across 90 degree creases.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "radiosity/shaded_mesh.h"
#include "radiosity/solver.h"
#include "tests/support/shaded_scenes.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

TEST(SolvedMesh, IsConformingAndContinuousWithinEachSmoothRegion) {
    const PatchMesh mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(0.5), Rgb::Constant(1)));
    SolverOptions o;
    o.rays = 100'000;
    o.epsilon = 1e-4;
    const Solution sol = solve(mesh, o);
    const ShadedMesh m = build_shaded_mesh(*sol.hierarchy);
    ASSERT_EQ(m.cell_count(), sol.stats.leaves);
    ASSERT_GT(m.cell_count(), 500u);
    EXPECT_TRUE(conforming(m));

    // Within one face of the box (4 coplanar patches) every position has a single point: the
    // vertex values are continuous across element and patch boundaries there.
    std::map<std::tuple<int, double, double, double>, std::int64_t> point_at;
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        const int face = m.patch_id[c] / 4;
        for (auto i = m.offsets[c]; i < m.offsets[c + 1]; ++i) {
            const auto p = m.connectivity[i];
            const auto key = std::tuple(face, m.points[p].x(), m.points[p].y(), m.points[p].z());
            const auto [it, inserted] = point_at.emplace(key, p);
            EXPECT_EQ(it->second, p) << "two points at one position on face " << face;
        }
    }
}

}  // namespace
}  // namespace hmcr::test
