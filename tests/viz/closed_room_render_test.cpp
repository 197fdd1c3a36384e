// SPDX-License-Identifier: Apache-2.0
// A render of a closed, lit room has no black pixel: every ray from inside meets a lit surface,
// also where it passes exactly through the edge two cells share or along a T-vertex's edge
// (viz/shaded_tracer.h). The views have an odd number of pixels, so that the middle row and
// column of rays run through the room's symmetric patch corners and edges.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radiosity/solver.h"
#include "tests/support/test_scenes.h"
#include "viz/renderer.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

// The Cornell box's measures closed on every side, 3 x 3 grey quads a wall, the ceiling's
// middle quad a light; solved with refinement, so that the leaves have T-vertices.
ShadedMesh solved_closed_room(const Vec3& lo, const Vec3& hi) {
    std::vector<test::TestPolygon> walls =
        test::inward_box(lo, hi, 3, Rgb::Constant(0.6), Rgb::Zero());
    for (test::TestPolygon& w : walls) {
        Vec3 centre = Vec3::Zero();
        for (const Vec3& p : w.corners) centre += p / double(w.corners.size());
        const Vec3 off = centre - (lo + hi) / 2;
        if (centre.y() == hi.y() && std::abs(off.x()) < 0.1 && std::abs(off.z()) < 0.1) {
            w.emission = Rgb::Constant(10);
        }
    }
    SolverOptions options;
    options.rays = 200'000;
    return shade(solve(test::make_patch_mesh(walls), options), 30);
}

TEST(ClosedRoomRender, NoPixelIsBlackAtOneSamplePerPixel) {
    const Vec3 lo(0, 0, 0), hi(0.556, 0.5488, 0.5592), c = (lo + hi) / 2;
    const ShadedMesh mesh = solved_closed_room(lo, hi);
    ASSERT_GT(mesh.cell_count(), 9u * 6u) << "the solve refined nothing";
    const ShadedTracer tracer(mesh);
    // From the middle towards each wall's middle and two corners.
    const std::vector<Vec3> targets = {{c.x(), c.y(), hi.z()},
                                       {c.x(), c.y(), lo.z()},
                                       {hi.x(), c.y(), c.z()},
                                       {lo.x(), c.y(), c.z()},
                                       {c.x(), hi.y(), c.z()},
                                       {c.x(), lo.y(), c.z()},
                                       hi,
                                       lo};
    for (const Vec3& target : targets) {
        View view = test::test_view(c, target, 90, 127);
        if (target.x() == c.x() && target.z() == c.z()) view.up = Vec3(0, 0, 1);
        const Image image = render(tracer, view, {1});
        int black = 0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                if (image.at(x, y).maxCoeff() > 0) continue;
                if (black++ == 0) {
                    ADD_FAILURE() << "looking at (" << target.transpose() << "): pixel (" << x
                                  << ", " << y << ") is black";
                }
            }
        }
        EXPECT_EQ(black, 0) << "black pixels looking at (" << target.transpose() << ")";
    }
}

}  // namespace
}  // namespace hmcr
