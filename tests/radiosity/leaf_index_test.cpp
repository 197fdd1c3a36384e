// SPDX-License-Identifier: Apache-2.0
// A fixed mesh's leaves by parameter point (radiosity/leaf_index.h): the same leaf as the
// walk down the elements, on quads and triangles, on both sides, at and beside every boundary.
#include "radiosity/leaf_index.h"

#include <gtest/gtest.h>

#include <cmath>

#include "rays/rng.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {
namespace {

// A rectangle, a skewed quad and a triangle, all two-sided.
std::vector<TestPolygon> two_sided_polygons() {
    std::vector<TestPolygon> polygons = {
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, Rgb::Constant(0.5), Rgb::Zero()},
        {{{2, 0, 0}, {4, 0, 0}, {3.6, 1.2, 0}, {2.2, 0.9, 0}}, Rgb::Constant(0.5), Rgb::Zero()},
        {{{5, 0, 0}, {7, 0.5, 0}, {5.5, 2, 0}}, Rgb::Constant(0.5), Rgb::Constant(1)}};
    for (TestPolygon& p : polygons) {
        p.two_sided = true;
        p.back_reflectance = Rgb::Constant(0.3);
    }
    return polygons;
}

// Splits e and, with probability 3/4, each child again, down to `depth` levels: uneven trees.
void split_randomly(Hierarchy& h, Element& e, int depth, Rng& rng) {
    if (depth == 0) return;
    Element* c = h.subdivide(e);
    for (int k = 0; k < 4; ++k) {
        if (rng.uniform() < 0.75) split_randomly(h, c[k], depth - 1, rng);
    }
}

double pick(const std::vector<double>& values, Rng& rng) {
    return values[std::size_t(rng.uniform() * double(values.size()))];
}

// Points of a patch's domain that a walk must decide exactly: dyadic boundaries of the depths
// the trees reach, the floats on either side of them, the domain's edges, and random points.
std::vector<Vec2> hard_points(bool quad, Rng& rng) {
    // Beyond the domain too (-1e-7, 1 + 1e-7): the walks must agree there as well.
    std::vector<double> coordinates = {0,    1,     std::nextafter(1.0f, 0.0f), 1e-30,
                                       1e-7, -1e-7, std::nextafter(1.0f, 2.0f)};
    for (int depth = 1; depth <= 10; ++depth) {
        const double step = std::ldexp(1.0, -depth);
        for (double x = step; x < 1; x += 2 * step) {
            coordinates.push_back(x);
            coordinates.push_back(std::nextafter(float(x), 0.0f));
            coordinates.push_back(std::nextafter(float(x), 1.0f));
        }
    }
    std::vector<Vec2> points;
    for (int k = 0; k < 20000; ++k) {
        const double u = k % 2 ? pick(coordinates, rng) : rng.uniform();
        const double v = k % 3 ? pick(coordinates, rng) : rng.uniform();
        // Hits carry float parameters; a triangle's are in u + v <= 1.
        Vec2 uv{float(u), float(v)};
        if (!quad && uv.sum() > 1) uv = Vec2(float(1 - v), float(1 - u));
        if (!quad && uv.sum() > 1) continue;
        points.push_back(uv);
    }
    return points;
}

TEST(LeafIndex, FindsTheLeafTheWalkDownTheElementsFinds) {
    Hierarchy h(build_patch_set(make_patch_mesh(two_sided_polygons())), {.max_depth = 12});
    Rng rng(11, 0);
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        split_randomly(h, h.root(p), 9, rng);
        if (p != 1) split_randomly(h, h.root(p, kBack), 6, rng);  // patch 1's back stays unmade
    }
    const LeafIndex index(h);
    std::size_t checked = 0, deep = 0;
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        for (std::uint8_t side : {kFront, kBack}) {
            if (!h.back_root(p) && side == kBack) continue;
            for (const Vec2& uv : hard_points(h.patch_set().patches[p].is_quad(), rng)) {
                const Element& walked = h.locate(h.root(p, side), uv);
                ASSERT_EQ(&index.locate(std::uint32_t(p), side, uv), &walked)
                    << "patch " << p << " side " << int(side) << " uv " << uv.transpose();
                ++checked;
                deep += walked.id.depth >= 5;
            }
        }
    }
    EXPECT_GT(checked, 90000u);
    // A random point's leaf is at depth 5 or more with probability (3/4)^4 = 0.32.
    EXPECT_GT(deep, checked / 5);
}

// A side without a root when the index was made, or with a root that is a leaf, is its own
// leaf; the index makes the missing back root as the hierarchy does, and finds it again.
TEST(LeafIndex, AnUnsplitOrUnmadeSideIsItsOwnLeaf) {
    Hierarchy h(build_patch_set(make_patch_mesh(two_sided_polygons())), {});
    h.subdivide(h.root(0));
    const LeafIndex index(h);
    EXPECT_EQ(&index.locate(1, kFront, Vec2(0.3, 0.6)), &h.root(1));
    ASSERT_EQ(h.back_root(0), nullptr);
    Element& back = index.locate(0, kBack, Vec2(0.3, 0.6));
    EXPECT_EQ(h.back_root(0), &back);
    EXPECT_TRUE(back.is_leaf());
    EXPECT_EQ(&index.locate(0, kBack, Vec2(0.9, 0.1)), &back);
    EXPECT_EQ(&index.locate(0, kFront, Vec2(0.75, 0.25)), &h.root(0).children()[1]);
}

// Without two-sided patches the index holds the fronts alone, and finds a leaf below a middle
// triangle, whose domain is inverted.
TEST(LeafIndex, IndexesTheFrontsOfOneSidedPatches) {
    std::vector<TestPolygon> polygons = two_sided_polygons();
    for (TestPolygon& p : polygons) p.two_sided = false;
    Hierarchy h(build_patch_set(make_patch_mesh(polygons)), {});
    Element* c = h.subdivide(h.root(2));
    h.subdivide(c[3]);
    const LeafIndex index(h);
    EXPECT_EQ(&index.locate(2, kFront, Vec2(0.3, 0.3)), &c[3].children()[3]);
    EXPECT_EQ(&index.locate(2, kFront, Vec2(0.4, 0.4)), &c[3].children()[0]);
    EXPECT_EQ(&index.locate(2, kFront, Vec2(0.1, 0.45)), &c[3].children()[1]);
    EXPECT_EQ(&index.locate(2, kFront, Vec2(0.1, 0.1)), &c[0]);
    EXPECT_EQ(&index.locate(0, kFront, Vec2(0.1, 0.1)), &h.root(0));
}

}  // namespace
}  // namespace hmcr::test
