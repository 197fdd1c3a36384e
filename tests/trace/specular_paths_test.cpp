// SPDX-License-Identifier: Apache-2.0
// The path tracer with specular surfaces against exact radiance (docs/design.md §10.1-§10.2): a
// closed furnace of mirrors, diffuse and mixed walls of one albedo; an emitter seen in a mirror;
// next-event estimation with MIS against pure path tracing on the bundled `mirrors`; and the
// same bits for any thread count. Each Monte Carlo check is a hypothesis test on the mean over an
// image's pixels (independent streams), as in path_tracer_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "meshes/scene.h"
#include "rays/camera.h"
#include "tests/support/image_checks.h"
#include "tests/support/statistics.h"
#include "tests/support/test_scenes.h"
#include "trace/criteria/registry.h"
#include "trace/path_tracer.h"
#include "trace/pixel_run.h"
#include "trace/trace_image.h"

namespace hmcr::test::specular_paths {
namespace {

constexpr double kPi = std::numbers::pi;

TraceResult trace(const PatchMesh& mesh, const View& v, Estimator e, int spp, std::uint64_t seed,
                  const Criterion& sampler = uniform_criterion(), int threads = 0,
                  Allocation allocation = Allocation::refine) {
    PathOptions path;
    path.estimator = e;
    const PathTracer tracer(build_patch_set(mesh), path);
    TraceOptions o;
    o.sampler = &sampler;
    o.spp = spp;
    o.seed = seed;
    o.threads = threads;
    o.allocation = allocation;
    o.path = path;
    return trace_image(tracer, v, o);
}

std::vector<double> channel(const Image& a, int c, const Image* minus = nullptr) {
    std::vector<double> v;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        v.push_back(a.pixels[i][c] - (minus ? minus->pixels[i][c] : 0.0));
    return v;
}

// The unit cube, every wall of albedo rho and emitting E: the x walls ideal mirrors (Ks = rho),
// the y walls diffuse (Kd = rho), the z walls half of each; the same furnace in every way.
PatchMesh mixed_furnace(double rho, double e) {
    std::vector<TestPolygon> walls = inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Zero(), Rgb::Zero());
    for (TestPolygon& w : walls) {
        const Vec3 n = (w.corners[1] - w.corners[0]).cross(w.corners[2] - w.corners[0]);
        const int axis = std::abs(n.x()) > 0.5 * n.norm()   ? 0
                         : std::abs(n.y()) > 0.5 * n.norm() ? 1
                                                            : 2;
        w.emission = Rgb::Constant(e);
        w.reflectance = Rgb::Constant(axis == 0 ? 0 : axis == 1 ? rho : rho / 2);
        w.specular = Rgb::Constant(axis == 0 ? rho : axis == 1 ? 0 : rho / 2);
    }
    return make_patch_mesh(walls);
}

// L = Le / (1 - rho) = E / (pi (1 - rho)) wherever the camera looks: at a mirror wall, a diffuse
// one and a mixed one, each view seeing that wall alone, with MIS and with BSDF sampling alone.
TEST(SpecularPaths, MixedMirrorAndDiffuseFurnaceIsEmissionOverOneMinusRho) {
    const double rho = 0.5, e = 1, expected = e / (kPi * (1 - rho));
    const PatchMesh mesh = mixed_furnace(rho, e);
    const View walls[] = {test_view({0.7, 0.5, 0.45}, {0, 0.52, 0.5}, 60, 24),   // mirror, x = 0
                          test_view({0.45, 0.7, 0.5}, {0.5, 0, 0.52}, 60, 24),   // diffuse, y = 0
                          test_view({0.5, 0.45, 0.7}, {0.52, 0.5, 0}, 60, 24)};  // mixed, z = 0
    const double bias = std::pow(rho, PathOptions{}.max_depth + 1) / (1 - rho) * e / kPi;
    for (const Estimator est : {Estimator::mis, Estimator::bsdf}) {
        for (const View& v : walls) {
            const Image im = trace(mesh, v, est, 8, 11).image;
            for (int c = 0; c < 3; ++c) {
                const Estimate m = estimate_mean(channel(im, c));
                EXPECT_TRUE(within_standard_errors(estimator_name(est) + " furnace", m.mean,
                                                   expected, m.standard_error, bias));
            }
        }
    }
}

// A mirror of reflectance rho_s (z = 0, facing up) under a large emitter of radiance Le
// (z = 2, facing down), seen from between them: every pixel is rho_s Le, exactly, whatever the
// estimator (next-event estimation cannot sample the mirror's reflection, so the emitter it
// shows counts whole).
TEST(SpecularPaths, AnEmitterSeenInAMirrorHasRhoSTimesItsRadiance) {
    const Rgb rho_s(0.8, 0.5, 0.2), le(1, 2, 3);
    TestPolygon mirror = axis_rectangle(2, 0, {-1, -1}, {1, 1}, true);
    mirror.specular = rho_s;
    TestPolygon light = axis_rectangle(2, 2, {-20, -20}, {20, 20}, false);
    light.emission = kPi * le;
    const PatchMesh mesh = make_patch_mesh({mirror, light});
    View v = test_view({0, 0, 1}, {0, 0.01, 0}, 40, 16);
    for (const Estimator est : {Estimator::mis, Estimator::nee, Estimator::bsdf}) {
        const Image im = trace(mesh, v, est, 4, 2).image;
        for (const Rgb& p : im.pixels)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(p[c], rho_s[c] * le[c], 1e-12) << estimator_name(est);
    }
}

// Each pixel's mean radiance and the variance of that mean, from the pixel's own samples (its
// uniform batches): the sample variance over n, which stratification can only make smaller.
struct PixelMeans {
    std::vector<Rgb> mean, variance;
};

PixelMeans pixel_means(const PatchMesh& mesh, const View& v, Estimator e, std::uint32_t spp,
                       std::uint64_t seed) {
    PathOptions path;
    path.estimator = e;
    const PathTracer tracer(build_patch_set(mesh), path);
    const Camera camera = make_camera(v);
    const PixelTracer pixels(tracer, camera, seed);
    PixelMeans out;
    for (int y = 0; y < v.height; ++y)
        for (int x = 0; x < v.width; ++x) {
            Rgb sum = Rgb::Zero(), squares = Rgb::Zero();
            for (std::uint32_t first = 0; first < spp; first += kBatchSize)
                for (const TracedSample& t :
                     trace_pixel_batch(pixels, x, y, first, std::min(first + kBatchSize, spp))) {
                    sum += t.sample.radiance;
                    squares += t.sample.radiance * t.sample.radiance;
                }
            const double n = spp;
            const Rgb mean = sum / n;
            out.mean.push_back(mean);
            out.variance.push_back((squares - n * mean * mean) / ((n - 1) * n));
        }
    return out;
}

// On the bundled mirrors (both views), next-event estimation with and without MIS and pure path
// tracing estimate the same pixel means: the mean over the image of their per-pixel difference
// is 0 within kZ standard errors, the standard error from each pixel's own sample variance
// (independent seeds; 12 comparisons at z = 4 keep the family's false alarms below 1e-3). The
// within-pixel variance, not the spread of the differences across pixels, is what makes the test
// sensitive to a bias confined to a few pixels (reflected lights, light the mirrors throw onto
// the table): losing the emitters seen through a mirror puts it 4.4 to 6.4 standard errors out.
TEST(SpecularPaths, NextEventAndPurePathTracingAgreeOnMirrors) {
    const Scene scene = load_scene("mirrors");
    for (const View& full : scene.views) {
        View v = full;
        v.width = v.height = 24;
        const PixelMeans bsdf = pixel_means(scene.mesh, v, Estimator::bsdf, 128, 1);
        for (const Estimator e : {Estimator::mis, Estimator::nee}) {
            const PixelMeans other = pixel_means(scene.mesh, v, e, 32, 2 + std::uint64_t(e));
            for (int c = 0; c < 3; ++c) {
                double difference = 0, variance = 0;
                for (std::size_t i = 0; i < bsdf.mean.size(); ++i) {
                    difference += other.mean[i][c] - bsdf.mean[i][c];
                    variance += other.variance[i][c] + bsdf.variance[i][c];
                }
                const double n = double(bsdf.mean.size());
                EXPECT_TRUE(within_standard_errors(v.name + ": " + estimator_name(e) + " - bsdf",
                                                   difference / n, 0, std::sqrt(variance) / n));
            }
        }
    }
}

// Mirrors and glossy lobes draw from each sample's own stream: 1 and 2 threads give the same
// bits, for the uniform sampler, a batch one, the Cycles-style passes and the map allocation.
TEST(SpecularPaths, ImagesWithSpecularSurfacesDoNotDependOnTheThreadCount) {
    std::vector<TestPolygon> walls =
        inward_box({0, 0, 0}, {1, 1, 1}, 2, Rgb::Constant(0.3), Rgb::Zero());
    for (std::size_t k = 0; k < walls.size(); ++k) {
        if (k % 3 == 0) walls[k].specular = Rgb::Constant(0.5);
        if (k % 3 == 1) walls[k].specular = Rgb(0.4, 0.5, 0.6), walls[k].roughness = 0.15;
        if (k % 5 == 0) walls[k].emission = Rgb::Constant(2);
    }
    const PatchMesh mesh = make_patch_mesh(walls);
    const View v = test_view({0.2, 0.5, 0.3}, {0.9, 0.4, 0.8}, 80, 20);
    const std::pair<const char*, Allocation> cases[] = {{"uniform", Allocation::refine},
                                                        {"srhe", Allocation::refine},
                                                        {"half-difference", Allocation::refine},
                                                        {"entropy", Allocation::map}};
    for (const auto& [name, allocation] : cases) {
        const Criterion& c = *criterion_registry().find(name);
        const TraceResult one = trace(mesh, v, Estimator::mis, 16, 5, c, 1, allocation);
        const TraceResult two = trace(mesh, v, Estimator::mis, 16, 5, c, 2, allocation);
        EXPECT_TRUE(identical(one.image, two.image)) << name;
        EXPECT_EQ(one.samples, two.samples) << name;
    }
}

}  // namespace
}  // namespace hmcr::test::specular_paths
