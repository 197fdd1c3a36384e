// SPDX-License-Identifier: Apache-2.0
#include "viz/renderer.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <numbers>

#include "image/image.h"
#include "image/tone_map.h"
#include "tests/support/image_checks.h"

namespace hmcr {
namespace {

constexpr double kPi = std::numbers::pi;
using test::kFloatTol;

// The unit square in z = 0 as two cells, the right one with a point in the middle of its right
// edge (a conforming polygon's T-vertex), point radiosity B = pi * field(point).
template <class Field>
ShadedMesh unit_square(Field field) {
    ShadedMesh m;
    m.points = {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0}, {0, 1, 0}, {1, 0.5, 0}};
    for (const Vec3& p : m.points) m.point_radiosity.push_back(kPi * field(p));
    m.connectivity = {0, 1, 4, 5, 1, 2, 6, 3, 4};
    m.offsets = {0, 4, 9};
    m.patch_id = {0, 0};
    return m;
}

Rgb linear_field(const Vec3& p) {
    return Rgb(0.1 + 0.2 * p.x() + 0.3 * p.y(), 0.05 + 0.1 * p.x(), 0.4 * p.y());
}
Rgb constant_field(const Vec3&) { return Rgb(0.5, 0.25, 0.125); }

// 16 x 8 pixels, 90 degrees vertically, one unit above the square's centre: the image plane
// spans x in [-1.5, 2.5] (aspect 2) and y in [-0.5, 1.5] at z = 0, 0.25 per pixel, so the square
// covers columns 6..9 and rows 2..5, and pixel (x, y) is centred on the point below.
View square_view() {
    View v;
    v.name = "top";
    v.position = Vec3(0.5, 0.5, 1);
    v.look_at = Vec3(0.5, 0.5, 0);
    v.up = Vec3(0, 1, 0);
    v.fov_degrees = 90;
    v.width = 16;
    v.height = 8;
    return v;
}
Vec3 pixel_centre(int x, int y) { return Vec3((x + 0.5) / 4 - 1.5, 1.5 - (y + 0.5) / 4, 0); }
bool covered(int x, int y) { return x >= 6 && x <= 9 && y >= 2 && y <= 5; }

TEST(Renderer, LinearFieldGivesItsValuesAtPixelCentres) {
    for (const int n : {1, 2, 3}) {  // the mean of stratified samples of a linear field too
        const Image im = render(unit_square(linear_field), square_view(), {n});
        ASSERT_EQ(im.width, 16);
        ASSERT_EQ(im.height, 8);
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 16; ++x) {
                if (!covered(x, y)) {
                    EXPECT_EQ(im.at(x, y).matrix(), Vec3::Zero()) << x << "," << y;
                    continue;
                }
                // Radiance B / pi is the field itself.
                const Rgb expected = linear_field(pixel_centre(x, y));
                EXPECT_TRUE(((im.at(x, y) - expected).abs() < kFloatTol).all())
                    << "n " << n << " pixel " << x << "," << y << ": " << im.at(x, y).transpose()
                    << " expected " << expected.transpose();
            }
        }
    }
}

// The square's two cells seen from above: a pixel is inked where its right or lower neighbour
// shows another cell or the background; the rest of the image is left as it was.
TEST(Renderer, CellEdgesAreDrawnWhereNeighbouringPixelsSeeAnotherCell) {
    const View v = square_view();
    Image8 grey(v.width, v.height);
    for (Srgb8& p : grey.pixels) p = {100, 100, 100};
    const Image8 edges =
        draw_cell_edges(ShadedTracer(unit_square(constant_field)), v, grey, {255, 0, 0});
    for (int y = 0; y < v.height; ++y)
        for (int x = 0; x < v.width; ++x) {
            const bool column = (x == 5 || x == 7 || x == 9) && y >= 2 && y <= 5;
            const bool row = (y == 1 || y == 5) && x >= 6 && x <= 9;
            EXPECT_EQ(edges.at(x, y), (column || row ? Srgb8{255, 0, 0} : Srgb8{100, 100, 100}))
                << x << "," << y;
        }
    EXPECT_THROW(
        draw_cell_edges(ShadedTracer(unit_square(constant_field)), v, Image8(4, 4), {255, 0, 0}),
        std::invalid_argument);
}

TEST(Renderer, EightBitPixelsAreExposedSrgbQuantised) {
    const double exposure = 1.5;
    const Image8 im = quantise(render(unit_square(linear_field), square_view()), exposure);
    for (int y = 2; y <= 5; ++y) {
        for (int x = 6; x <= 9; ++x) {
            const Rgb expected = linear_field(pixel_centre(x, y));
            // The 8-bit value is exact unless float noise could cross a rounding boundary;
            // make sure the chosen field stays clear of those.
            for (int k = 0; k < 3; ++k) {
                const double code = 255 * srgb_encode(exposure * expected[k]);
                ASSERT_GT(std::abs(code - std::floor(code) - 0.5), 1e-3) << x << "," << y;
            }
            EXPECT_EQ(im.at(x, y), to_srgb8(expected, exposure)) << x << "," << y;
        }
    }
    EXPECT_EQ(im.at(0, 0), (Srgb8{0, 0, 0}));
    // By hand: centre of pixel (6, 5) is (0.125, 0.125); red radiance 0.1 + 0.025 + 0.0375 =
    // 0.1625, exposed 0.24375, sRGB 1.055 * 0.24375^(1/2.4) - 0.055 = 0.53089, 135.38 -> 135.
    EXPECT_EQ(im.at(6, 5)[0], 135);
}

TEST(Renderer, SupersamplingAveragesCoverage) {
    // Moved by half a pixel (0.125) to the left: the square's edges now cut columns 6 and 10 in
    // half, which n = 2 samples see as half covered; other covered pixels are exact.
    View v = square_view();
    v.position.x() -= 0.125;
    v.look_at.x() -= 0.125;
    const Image im = render(unit_square(constant_field), v, {2});
    const Rgb c = constant_field(Vec3::Zero());
    for (int y = 2; y <= 5; ++y) {
        EXPECT_TRUE(im.at(6, y).isApprox(c / 2, kFloatTol)) << im.at(6, y).transpose();
        for (int x = 7; x <= 9; ++x) EXPECT_TRUE(im.at(x, y).isApprox(c, kFloatTol));
        EXPECT_TRUE(im.at(10, y).isApprox(c / 2, kFloatTol));
        EXPECT_EQ(im.at(11, y).matrix(), Vec3::Zero());
        EXPECT_EQ(im.at(5, y).matrix(), Vec3::Zero());
    }
}

TEST(Renderer, UpIsOrthogonalisedAndThreadsDoNotMatter) {
    View tilted = square_view();
    tilted.up = Vec3(0, 3, 3);  // not orthogonal to the viewing direction; same camera
    const ShadedTracer tracer(unit_square(linear_field));
    const Image reference = render(tracer, square_view(), {3});
    EXPECT_TRUE(test::identical(render(tracer, tilted, {3}), reference));
    for (const int threads : {1, 2}) {
        tbb::task_arena arena(threads);
        const Image im = arena.execute([&] { return render(tracer, square_view(), {3}); });
        EXPECT_TRUE(test::identical(im, reference)) << threads << " threads";
    }
}

TEST(Renderer, RejectsBadViewsAndOptions) {
    const ShadedTracer tracer(unit_square(constant_field));
    View v = square_view();
    EXPECT_THROW(render(tracer, v, {0}), std::invalid_argument);
    v.up = Vec3(0, 0, 2);
    EXPECT_THROW(render(tracer, v), std::invalid_argument);
    v = square_view();
    v.look_at = v.position;
    EXPECT_THROW(render(tracer, v), std::invalid_argument);
    v = square_view();
    v.fov_degrees = 180;
    EXPECT_THROW(render(tracer, v), std::invalid_argument);
    v = square_view();
    v.width = 0;
    EXPECT_THROW(render(tracer, v), std::invalid_argument);
}

TEST(Renderer, ExposureMapsMeanForegroundLuminanceToMiddleGrey) {
    Image im(3, 1);  // one background pixel, two lit ones of luminance 0.2 and 0.4
    im.at(1, 0) = Rgb::Constant(0.2);
    im.at(2, 0) = Rgb(0, 0.4 / 0.7152, 0);
    EXPECT_NEAR(exposure_from(im), 0.18 / 0.3, 1e-12);
    EXPECT_EQ(exposure_from(Image(2, 2)), 1);  // all background
    // The rendered square with a constant field: every lit pixel has the same luminance.
    const Image square = render(unit_square(constant_field), square_view());
    EXPECT_NEAR(exposure_from(square), 0.18 / luminance(constant_field(Vec3::Zero())), 1e-6);
}

}  // namespace
}  // namespace hmcr
