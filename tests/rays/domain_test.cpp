// The descents' two ways of finding a point's child (rays/domain.h): the fixed-point digits of
// a quad point and the reciprocal form of child_containing give what child_containing gives,
// level by level down to the deepest split, for any float point, edges and strays included.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "rays/domain.h"
#include "rays/rng.h"

namespace hmcr::test {
namespace {

constexpr int kDeepest = QuadFixedPoint::kBits;  // an element at this depth is never split

// Points a descent may meet: uniform ones, and the ones where the comparisons tie or round.
std::vector<Vec2f> hostile_points() {
    std::vector<Vec2f> points;
    Rng rng(7, 0);
    for (int k = 0; k < 20'000; ++k) {
        points.emplace_back(float(rng.uniform()), float(rng.uniform()));
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float edges[] = {0.0f,
                           1.0f,
                           0.5f,
                           0.25f,
                           0.75f,
                           std::ldexp(1.0f, -kDeepest),
                           std::ldexp(1.0f, -30),
                           1e-30f,
                           std::nextafter(0.5f, 0.0f),
                           std::nextafter(1.0f, 0.0f),
                           std::nextafter(1.0f, 2.0f),
                           1.0f - std::ldexp(1.0f, -kDeepest),
                           -0.0f,
                           -1e-7f,
                           1.5f,
                           nan};
    for (const float u : edges) {
        for (const float v : edges) points.emplace_back(u, v);
    }
    // Dyadic points at every depth, and their neighbours on either side.
    for (int depth = 1; depth <= kDeepest; ++depth) {
        const float step = std::ldexp(1.0f, -depth);
        for (int k = 0; k < 8; ++k) {
            const float x = float(rng.uniform());
            const float dyadic = std::floor(x / step) * step;
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

TEST(Domain, QuadFixedPointDigitsAreChildContainingAtEveryDepth) {
    int compared = 0;
    for (const Vec2f& p : hostile_points()) {
        const QuadFixedPoint fixed = QuadFixedPoint::of(p.x(), p.y());
        Domain d = Domain::root();
        for (int depth = 0; depth < kDeepest; ++depth) {
            const int k = d.child_containing(true, p.cast<double>());
            ASSERT_EQ(fixed.child(depth), k)
                << "point (" << p.x() << ", " << p.y() << ") at depth " << depth;
            d = d.child(true, k);
            ++compared;
        }
    }
    EXPECT_GT(compared, 500'000);
}

// The reference: child_containing as the division it states.
int divided_child(const Domain& d, bool quad, const Vec2& uv) {
    const double a = (uv.x() - d.u0) / d.s, b = (uv.y() - d.v0) / d.s;
    if (quad) return (a >= 0.5 ? 1 : 0) + (b >= 0.5 ? 2 : 0);
    if (a >= 0.5) return 1;
    if (b >= 0.5) return 2;
    return a + b < 0.5 ? 0 : 3;
}

TEST(Domain, ReciprocalChildContainingIsTheDivisionOnQuadsAndTriangles) {
    for (const bool quad : {false, true}) {
        for (const Vec2f& p : hostile_points()) {
            const Vec2 uv = p.cast<double>();
            Domain d = Domain::root();
            for (int depth = 0; depth < kDeepest; ++depth) {
                const int k = divided_child(d, quad, uv);
                ASSERT_EQ(d.child_containing(quad, uv.x(), uv.y(), 1.0 / double(d.s)), k)
                    << (quad ? "quad" : "triangle") << " point (" << p.x() << ", " << p.y()
                    << ") at depth " << depth;
                d = d.child(quad, k);
            }
        }
    }
}

}  // namespace
}  // namespace hmcr::test
