// A walk down the subdivision without dividing (rays/domain.h) picks, level by level down to
// the deepest split, the child that child_containing's division picks, for any float point:
// dyadic boundaries, their neighbours, the edges and points beyond them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rays/domain.h"
#include "rays/rng.h"

namespace hmcr::test {
namespace {

constexpr int kDeepest = 24;  // an element at this depth is never split

std::vector<Vec2f> hostile_points() {
    std::vector<Vec2f> points;
    Rng rng(7, 0);
    for (int k = 0; k < 5'000; ++k) points.emplace_back(float(rng.uniform()), float(rng.uniform()));
    const float edges[] = {0.0f, 1.0f, 0.5f, 1e-30f, -1e-7f, 1.5f,
                           std::nextafter(1.0f, 0.0f), std::nextafter(1.0f, 2.0f),
                           std::ldexp(1.0f, -kDeepest)};
    for (const float u : edges) {
        for (const float v : edges) points.emplace_back(u, v);
    }
    for (int depth = 1; depth <= kDeepest; ++depth) {
        const float step = std::ldexp(1.0f, -depth);
        for (int k = 0; k < 8; ++k) {
            const float dyadic = std::floor(float(rng.uniform()) / step) * step;
            for (const float u : {dyadic, std::nextafter(dyadic, 0.0f), std::nextafter(dyadic, 1.0f)}) {
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

}  // namespace
}  // namespace hmcr::test
