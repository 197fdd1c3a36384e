// SPDX-License-Identifier: Apache-2.0
// A walk down the subdivision without dividing (rays/domain.h) picks, level by level down to
// the deepest split, the child that child_containing's division picks, for any float point:
// dyadic boundaries, their neighbours, the edges and points beyond them; and a quad's cell at a
// depth, found from the point's binary digits, is the domain that walk reaches there.
#include "rays/domain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rays/rng.h"

namespace hmcr::test {
namespace {

constexpr int kDeepest = 24;  // an element at this depth is never split

std::vector<Vec2f> hostile_points() {
    std::vector<Vec2f> points;
    Rng rng(7, 0);
    for (int k = 0; k < 5'000; ++k) points.emplace_back(float(rng.uniform()), float(rng.uniform()));
    const float edges[] = {0.0f,
                           1.0f,
                           0.5f,
                           1e-30f,
                           -1e-7f,
                           1.5f,
                           std::nextafter(1.0f, 0.0f),
                           std::nextafter(1.0f, 2.0f),
                           std::ldexp(1.0f, -kDeepest)};
    for (const float u : edges) {
        for (const float v : edges) points.emplace_back(u, v);
    }
    for (int depth = 1; depth <= kDeepest; ++depth) {
        const float step = std::ldexp(1.0f, -depth);
        for (int k = 0; k < 8; ++k) {
            const float dyadic = std::floor(float(rng.uniform()) / step) * step;
            for (const float u :
                 {dyadic, std::nextafter(dyadic, 0.0f), std::nextafter(dyadic, 1.0f)}) {
                points.emplace_back(u, float(rng.uniform()));
                points.emplace_back(float(rng.uniform()), u);
                points.emplace_back(u, 1.0f - u);  // on a triangle's diagonals
                points.emplace_back(u, step - u);
            }
        }
    }
    return points;
}

TEST(Domain, AWalkPicksTheChildrenChildContainingPicksAtEveryDepth) {
    const std::vector<Vec2f> points = hostile_points();
    std::size_t compared = 0;
    for (const bool quad : {false, true}) {
        for (const Vec2f& p : points) {
            const Vec2 uv = p.cast<double>();
            DomainWalk walk(quad, uv);
            Domain d = Domain::root();
            for (int depth = 0; depth < kDeepest; ++depth) {
                const int k = d.child_containing(quad, uv);
                ASSERT_EQ(walk.step(), k) << (quad ? "quad" : "triangle") << " point (" << p.x()
                                          << ", " << p.y() << ") at depth " << depth;
                d = d.child(quad, k);
                ++compared;
            }
        }
    }
    EXPECT_EQ(compared, 2 * points.size() * kDeepest);
}

// A quad's cell at a depth, looked up from the point's digits, is the domain the walk from the
// root reaches at that depth, by the children quad_cell_child names, and a walk started there
// goes on as the walk from the root does.
TEST(Domain, AQuadCellIsWhereTheWalkFromTheRootArrives) {
    const std::vector<Vec2f> points = hostile_points();
    std::size_t compared = 0;
    for (const Vec2f& p : points) {
        const Vec2 uv = p.cast<double>();
        Domain d = Domain::root();
        std::vector<int> path;  // the children from the root
        for (int depth = 1; depth < kDeepest; ++depth) {
            path.push_back(d.child_containing(true, uv));
            d = d.child(true, path.back());
            const std::uint32_t i = Domain::quad_cell(uv.x(), depth),
                                j = Domain::quad_cell(uv.y(), depth);
            const Domain cell = Domain::quad_cell_domain(i, j, depth);
            ASSERT_TRUE(cell.u0 == d.u0 && cell.v0 == d.v0 && cell.s == d.s)
                << "point (" << p.x() << ", " << p.y() << ") at depth " << depth;
            for (int level = 0; level < depth; ++level) {
                ASSERT_EQ(Domain::quad_cell_child(i, j, level), path[depth - 1 - level])
                    << "point (" << p.x() << ", " << p.y() << ") at depth " << depth;
            }
            DomainWalk from_cell(true, uv, cell);
            Domain below = d;
            for (int k = depth; k < std::min(depth + 3, kDeepest); ++k) {
                const int child = below.child_containing(true, uv);
                ASSERT_EQ(from_cell.step(), child)
                    << "point (" << p.x() << ", " << p.y() << ") from depth " << depth;
                below = below.child(true, child);
            }
            ++compared;
        }
    }
    EXPECT_EQ(compared, points.size() * (kDeepest - 1));
    // Every comparison of a walk fails for NaN, which so goes to the first child at every
    // level: the first cell.
    DomainWalk nan_walk(true, Vec2(std::nan(""), std::nan("")));
    for (int depth = 0; depth < 5; ++depth) ASSERT_EQ(nan_walk.step(), 0);
    EXPECT_EQ(Domain::quad_cell(std::nan(""), 5), 0u);
}

}  // namespace
}  // namespace hmcr::test
