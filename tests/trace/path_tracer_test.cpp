// SPDX-License-Identifier: Apache-2.0
// The path tracer against exact radiance: a closed furnace, a directly lit plate,
// and its estimators against each other. Each is a hypothesis test on the mean over an image's
// pixels, whose standard error comes from the pixels' own sample variance (pixels draw from
// independent streams).
#include "trace/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "meshes/scene.h"
#include "tests/support/analytic.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"
#include "trace/trace_image.h"

namespace hmcr::test {
namespace {

constexpr double kPi = std::numbers::pi;

Image trace(const PatchMesh& mesh, const View& v, const PathOptions& path, int spp,
            std::uint64_t seed) {
    const PathTracer tracer(build_patch_set(mesh), path);
    TraceOptions o;
    o.spp = spp;
    o.seed = seed;
    o.path = path;
    return trace_image(tracer, v, o).image;
}

// Channel c of every pixel, or of the difference of two images.
std::vector<double> channel(const Image& a, int c, const Image* minus = nullptr) {
    std::vector<double> v;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        v.push_back(a.pixels[i][c] - (minus ? minus->pixels[i][c] : 0.0));
    }
    return v;
}

PathOptions path(Estimator e, int roulette_depth = 3) {
    PathOptions p;
    p.estimator = e;
    p.roulette_depth = roulette_depth;
    return p;
}

class EveryEstimator : public testing::TestWithParam<Estimator> {};
class FiniteVarianceEstimator : public testing::TestWithParam<Estimator> {};

// A closed cube, rho = 0.5 and E = 1 everywhere: L = E / (pi (1 - rho)) = 2 / pi in every pixel
// and every direction. Paths longer than max_depth bounces are cut: a bias of
// rho^(max_depth + 1) / (1 - rho) E / pi, stated. Russian roulette from the first bounce on and
// from the third must both be unbiased. Next-event estimation alone is left out: near an edge
// its 1 / r^2 to the neighbouring face has infinite variance, so no standard error bounds it
// (with MIS the cosine sampling takes those directions over).
TEST_P(FiniteVarianceEstimator, FurnaceRadianceIsEmissionOverOneMinusRho) {
    const double rho = 0.5, e = 1;
    const auto mesh =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(rho), Rgb::Constant(e)));
    const View v = test_view({0.3, 0.6, 0.1}, {0.7, 0.4, 0.9}, 100, 32);
    for (const int roulette : {1, 3}) {
        const PathOptions p = path(GetParam(), roulette);
        const Image im = trace(mesh, v, p, 4, 17 + std::uint64_t(roulette));
        const double bias = std::pow(rho, p.max_depth + 1) / (1 - rho) * e / kPi;
        for (int c = 0; c < 3; ++c) {
            const Estimate m = estimate_mean(channel(im, c));
            EXPECT_TRUE(within_standard_errors(
                estimator_name(GetParam()) + " furnace, roulette " + std::to_string(roulette),
                m.mean, e / (kPi * (1 - rho)), m.standard_error, bias));
        }
    }
}

// The bundled plates: a unit emitter (E = 1, rho = 0) and a unit receiver (rho = 0.5) 1 m
// above it. A camera half-way between them, looking up with a 90 degree field of view, sees
// exactly the receiver, and its image plane is parallel to it, so the mean over the pixels is
// the mean radiance of the receiver, rho E F / pi, F the plates' form factor.
TEST_P(EveryEstimator, PlatesReceiverRadianceIsRhoEFOverPi) {
    const Scene scene = load_scene("plates");
    const View v = test_view({0.5, 0.5, 0.5}, {0.5, 0.5, 1}, 90, 48);
    const Image im = trace(scene.mesh, v, path(GetParam()), 4, 5);
    const double expected = 0.5 * 1 * parallel_rectangles(1, 1, 1) / kPi;
    for (int c = 0; c < 3; ++c) {
        const Estimate m = estimate_mean(channel(im, c));
        EXPECT_TRUE(within_standard_errors(estimator_name(GetParam()) + " plates", m.mean, expected,
                                           m.standard_error));
    }
}

INSTANTIATE_TEST_SUITE_P(PathTracer, FiniteVarianceEstimator,
                         testing::Values(Estimator::mis, Estimator::bsdf),
                         [](const auto& p) { return estimator_name(p.param); });
INSTANTIATE_TEST_SUITE_P(PathTracer, EveryEstimator,
                         testing::Values(Estimator::mis, Estimator::nee, Estimator::bsdf),
                         [](const auto& p) { return estimator_name(p.param); });

// On the Cornell box, with shadows, occluders and interreflection, next-event estimation (with
// and without MIS) and pure path tracing estimate the same pixel means: the mean over the
// pixels of their per-pixel difference is 0 within its standard error (independent seeds).
TEST(PathTracer, NextEventAndPurePathTracingAgreeOnTheCornellBox) {
    const Scene scene = load_scene("cornell");
    View v = find_view(scene, "camera");
    v.width = v.height = 48;
    const Image bsdf = trace(scene.mesh, v, path(Estimator::bsdf), 256, 1);
    for (const Estimator e : {Estimator::mis, Estimator::nee}) {
        const Image other = trace(scene.mesh, v, path(e), 64, 2 + std::uint64_t(e));
        for (int c = 0; c < 3; ++c) {
            const Estimate d = estimate_mean(channel(other, c, &bsdf));
            EXPECT_TRUE(
                within_standard_errors(estimator_name(e) + " - bsdf", d.mean, 0, d.standard_error));
        }
    }
}

TEST(PathTracer, RefusesBadOptionsAndScenesWithoutLight) {
    const auto dark =
        make_patch_mesh(inward_box({0, 0, 0}, {1, 1, 1}, 1, Rgb::Constant(0.5), Rgb::Zero()));
    EXPECT_THROW(PathTracer(build_patch_set(dark), PathOptions{}), std::invalid_argument);
    const Scene scene = load_scene("plates");
    PathOptions bad;
    bad.roulette_depth = 0;
    EXPECT_THROW(PathTracer(build_patch_set(scene.mesh), bad), std::invalid_argument);
}

}  // namespace
}  // namespace hmcr::test
