// SPDX-License-Identifier: Apache-2.0
// The path tracer's sides (docs/design.md §1.3, §10.1) against exact radiance: a two-sided plate
// lit from both sides shows each side's light, a back that emits is found by every estimator,
// a two-sided mirror mirrors on its back, and a one-sided patch's back stays black. Each mean is
// a hypothesis test over an image's pixels, whose standard error comes from the pixels' own
// sample variance (pixels draw from independent streams).
#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "tests/support/analytic.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"
#include "trace/path_tracer.h"
#include "trace/trace_image.h"

namespace hmcr::test::two_sided_paths {
namespace {

constexpr double kPi = std::numbers::pi;
const Rgb kFrontRho(0.5, 0.4, 0.3), kBackRho(0.25, 0.2, 0.1);

Image trace(const std::vector<TestPolygon>& scene, const View& v, Estimator e, int spp = 4) {
    PathOptions path;
    path.estimator = e;
    const PathTracer tracer(build_patch_set(make_patch_mesh(scene)), path);
    TraceOptions o;
    o.spp = spp;
    o.seed = 11 + std::uint64_t(e);
    o.path = path;
    return trace_image(tracer, v, o).image;
}

std::vector<double> channel(const Image& im, int c) {
    std::vector<double> v;
    for (const auto& p : im.pixels) v.push_back(p[c]);
    return v;
}

// Half-way between the plate at z = 1 and a plane 1 m away, with a 90 degree field of view and
// the image plane parallel to the plate: the view sees exactly the unit plate, and the mean
// over its pixels is the plate's mean radiance (a parallel plane maps to the image by a scaling).
View below_plate() { return test_view({0.5, 0.5, 0.5}, {0.5, 0.5, 1}, 90, 32); }
View above_plate() { return test_view({0.5, 0.5, 1.5}, {0.5, 0.5, 1}, 90, 32); }

// Unit squares 1 m apart: emitter A (E = 1) at z = 0 facing up, the plate at z = 1 whose front
// faces A (rho kFrontRho) and whose back (kBackRho) faces up, and emitter B (E = 2) at z = 2
// facing down. Emitters are black: each side of the plate reflects its own emitter's light
// alone, L = rho E F / pi, F the form factor of the unit squares.
std::vector<TestPolygon> plate_between_emitters(bool two_sided) {
    TestPolygon a = axis_rectangle(2, 0, {0, 0}, {1, 1}, true);
    a.emission = Rgb::Constant(1);
    TestPolygon plate = axis_rectangle(2, 1, {0, 0}, {1, 1}, false);
    plate.reflectance = kFrontRho;
    plate.two_sided = two_sided;
    plate.back_reflectance = kBackRho;
    TestPolygon b = axis_rectangle(2, 2, {0, 0}, {1, 1}, false);
    b.emission = Rgb::Constant(2);
    return {a, plate, b};
}

void expect_radiance(const std::string& what, const Image& im, const Rgb& expected) {
    for (int c = 0; c < 3; ++c) {
        const Estimate m = estimate_mean(channel(im, c));
        EXPECT_TRUE(within_standard_errors(what + ", channel " + std::to_string(c), m.mean,
                                           expected[c], m.standard_error));
    }
}

void expect_every_pixel(const std::string& what, const Image& im, const Rgb& expected) {
    for (std::size_t i = 0; i < im.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(im.pixels[i][c], expected[c], 1e-6 * (1 + expected[c]))
                << what << ", pixel " << i << ", channel " << c;
        }
    }
}

class EverySideEstimator : public testing::TestWithParam<Estimator> {};

TEST_P(EverySideEstimator, EachSideOfAPlateShowsTheLightOfTheEmitterItFaces) {
    const double f = parallel_rectangles(1, 1, 1);
    const std::string name = estimator_name(GetParam());
    const auto scene = plate_between_emitters(true);
    expect_radiance(name + " front", trace(scene, below_plate(), GetParam()), kFrontRho * f / kPi);
    expect_radiance(name + " back", trace(scene, above_plate(), GetParam()),
                    kBackRho * 2 * f / kPi);
}

TEST_P(EverySideEstimator, TheBackOfAOneSidedPlateIsBlack) {
    const double f = parallel_rectangles(1, 1, 1);
    const std::string name = estimator_name(GetParam());
    const auto scene = plate_between_emitters(false);
    expect_radiance(name + " front", trace(scene, below_plate(), GetParam()), kFrontRho * f / kPi);
    expect_every_pixel(name + " back", trace(scene, above_plate(), GetParam()), Rgb::Zero());
}

// Emitter B turned over: its front (E = 0.7) faces up into the void, its back (E = 2) faces the
// plate. Light sampling must find the back (next-event estimation alone sees nothing else),
// a bounce must take its emission, and MIS must weigh the two with the back's density: every
// estimator gives the plate's back the radiance of the test above. Seen from below, B's back
// shows its own L = E / pi in every pixel.
TEST_P(EverySideEstimator, AnEmittingBackIsFoundByLightSamplingAndByBounces) {
    const double f = parallel_rectangles(1, 1, 1);
    const std::string name = estimator_name(GetParam());
    std::vector<TestPolygon> scene = plate_between_emitters(true);
    TestPolygon& b = scene[2];
    b = axis_rectangle(2, 2, {0, 0}, {1, 1}, true);
    b.emission = Rgb::Constant(0.7);
    b.two_sided = true;
    b.back_emission = Rgb::Constant(2);
    expect_radiance(name + " plate's back", trace(scene, above_plate(), GetParam()),
                    kBackRho * 2 * f / kPi);
    const View below_b = test_view({0.5, 0.5, 1.5}, {0.5, 0.5, 2}, 90, 16);
    expect_every_pixel(name + " emitter's back", trace(scene, below_b, GetParam(), 1),
                       Rgb::Constant(2 / kPi));
}

INSTANTIATE_TEST_SUITE_P(TwoSidedPaths, EverySideEstimator,
                         testing::Values(Estimator::mis, Estimator::nee, Estimator::bsdf),
                         [](const auto& p) { return estimator_name(p.param); });

// A two-sided plate whose back is a mirror (rho_s = 0.8, no diffuse part) under an emitter wide
// enough to fill its reflection: every pixel seen from above is rho_s E / pi exactly (a delta
// bounce, then the emitter, which reflects nothing). One-sided, the same back is black.
TEST(TwoSidedPaths, TheBackOfATwoSidedMirrorMirrors) {
    TestPolygon plate = axis_rectangle(2, 1, {0, 0}, {1, 1}, false);
    plate.reflectance = kFrontRho;
    plate.two_sided = true;
    plate.back_specular = Rgb::Constant(0.8);
    TestPolygon light = axis_rectangle(2, 2, {-1, -1}, {2, 2}, false);
    light.emission = Rgb::Constant(2);
    for (const Estimator e : {Estimator::mis, Estimator::nee, Estimator::bsdf}) {
        expect_every_pixel(estimator_name(e) + " two-sided",
                           trace({plate, light}, above_plate(), e, 1), Rgb::Constant(1.6 / kPi));
    }
    plate.two_sided = false;
    expect_every_pixel("one-sided", trace({plate, light}, above_plate(), Estimator::mis, 1),
                       Rgb::Zero());
}

}  // namespace
}  // namespace hmcr::test::two_sided_paths
