// SPDX-License-Identifier: Apache-2.0
// Whole traced images: every sampler reaches its spp target within 2%, an image does not
// depend on the thread count, and the image the search assembles from its probes' samples is
// the one a fresh render at the accepted threshold gives.
#include "trace/trace_image.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <numbers>

#include "common/error.h"
#include "meshes/scene.h"
#include "tests/support/analytic.h"
#include "tests/support/image_checks.h"
#include "tests/support/statistics.h"
#include "trace/criteria/registry.h"

namespace hmcr::test {
namespace {

// The Cornell box's camera at 40 x 40 pixels.
class Cornell {
public:
    Cornell() : m_scene(load_scene("cornell")), m_tracer(build_patch_set(m_scene.mesh), {}) {
        m_view = find_view(m_scene, "camera");
        m_view.width = m_view.height = 40;
    }
    TraceResult trace(const TraceOptions& o) const { return trace_image(m_tracer, m_view, o); }

private:
    Scene m_scene;
    PathTracer m_tracer;
    View m_view;
};

const Cornell& cornell() {
    static const Cornell c;
    return c;
}

TraceOptions options(const Criterion& c, double spp) {
    TraceOptions o;
    o.sampler = &c;
    o.spp = spp;
    o.seed = 3;
    return o;
}

class EverySampler : public testing::TestWithParam<const Criterion*> {};

TEST_P(EverySampler, ReachesTheSppTargetWithinTwoPercent) {
    const TraceResult r = cornell().trace(options(*GetParam(), 20));
    EXPECT_LE(std::abs(r.counts().mean - 20), 0.02 * 20) << r.counts().mean;
    EXPECT_GE(r.counts().min, GetParam()->scheme() == Scheme::quadtree ? 4u : 8u);
    EXPECT_LE(r.counts().max, max_samples_per_pixel(options(*GetParam(), 20)));
    EXPECT_LE(r.rays, r.rays_traced);
}

TEST_P(EverySampler, ImagesDoNotDependOnTheThreadCount) {
    TraceResult results[2];
    for (const int threads : {1, 2}) {
        tbb::task_arena arena(threads);
        arena.execute([&] { results[threads - 1] = cornell().trace(options(*GetParam(), 12)); });
    }
    EXPECT_TRUE(identical(results[0].image, results[1].image));
    EXPECT_EQ(results[0].samples, results[1].samples);
    EXPECT_EQ(results[0].rays_traced, results[1].rays_traced);
}

// The search's image is assembled from samples its probes traced at several thresholds; a
// render at the accepted threshold alone traces exactly those it keeps.
TEST_P(EverySampler, SearchedImageEqualsAFreshRenderAtItsThreshold) {
    if (GetParam()->scheme() == Scheme::uniform) GTEST_SKIP() << "no threshold";
    const TraceResult searched = cornell().trace(options(*GetParam(), 16));
    ASSERT_GT(searched.probes.size(), 1u);
    TraceOptions fixed = options(*GetParam(), 16);
    fixed.threshold = searched.threshold;
    const TraceResult fresh = cornell().trace(fixed);
    EXPECT_TRUE(identical(searched.image, fresh.image));
    EXPECT_EQ(searched.samples, fresh.samples);
    EXPECT_EQ(searched.rays, fresh.rays);
    EXPECT_EQ(fresh.rays, fresh.rays_traced);
}

INSTANTIATE_TEST_SUITE_P(Registry, EverySampler, testing::ValuesIn(criterion_registry().all()),
                         [](const auto& p) {
                             std::string name(p.param->name());
                             for (char& c : name) c = c == '-' ? '_' : c;
                             return name;
                         });

TEST(TraceImage, UniformGivesEveryPixelExactlyItsSamples) {
    TraceOptions o = options(find_named(criterion_registry(), "uniform"),
                             13);  // one full batch and a partial one
    const TraceResult r = cornell().trace(o);
    EXPECT_EQ(r.counts().min, 13u);
    EXPECT_EQ(r.counts().max, 13u);
    EXPECT_TRUE(r.probes.empty());
}

TEST(TraceImage, TargetsOutsideTheSamplersRangeAreInputErrors) {
    EXPECT_THROW(cornell().trace(options(find_named(criterion_registry(), "kl"), 4)), InputError);
    EXPECT_THROW(cornell().trace(options(find_named(criterion_registry(), "entropy"), 2000)),
                 InputError);
    EXPECT_THROW(cornell().trace(options(find_named(criterion_registry(), "uniform"), 2.5)),
                 InputError);
    TraceOptions o = options(find_named(criterion_registry(), "kl"), 20);
    o.max_spp = 16;
    EXPECT_THROW(cornell().trace(o), InputError);
}

// The second pass takes fresh samples at the counts the criterion chose: the same counts, a new
// image, the rays of both passes.
TEST(TraceImage, FreshSamplesKeepTheCountsAndAddTheirRays) {
    TraceOptions o = options(find_named(criterion_registry(), "srhe"), 16);
    const TraceResult first = cornell().trace(o);
    o.fresh = true;
    const TraceResult fresh = cornell().trace(o);
    EXPECT_EQ(fresh.samples, first.samples);
    EXPECT_EQ(fresh.threshold, first.threshold);
    EXPECT_GT(fresh.rays_traced, first.rays_traced);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < first.image.pixels.size(); ++i)
        differ += (fresh.image.pixels[i] != first.image.pixels[i]).any() ? 1 : 0;
    EXPECT_GT(differ, first.image.pixels.size() / 2);
}

// The bundled plates seen from half-way between them, looking up with a 90 degree field of view:
// the mean over the pixels is the receiver's mean radiance rho E F / pi (as in
// path_tracer_test.cpp). With fresh samples the adaptive image's pixels are independent and
// unbiased, so the mean over them is within its standard errors of it.
TEST(TraceImage, FreshAdaptiveImagesAreUnbiased) {
    const Scene scene = load_scene("plates");
    View v;
    v.name = "up";
    v.position = Vec3(0.5, 0.5, 0.5);
    v.look_at = Vec3(0.5, 0.5, 1);
    v.up = Vec3(0, 1, 0);
    v.fov_degrees = 90;
    v.width = v.height = 48;
    const PathTracer tracer(build_patch_set(scene.mesh), {});
    TraceOptions o = options(find_named(criterion_registry(), "kl"), 16);
    o.fresh = true;
    const Image im = trace_image(tracer, v, o).image;
    const double expected = 0.5 * 1 * parallel_rectangles(1, 1, 1) / std::numbers::pi;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> values;
        for (const Rgb& p : im.pixels) values.push_back(p[c]);
        const Estimate m = estimate_mean(values);
        EXPECT_TRUE(
            within_standard_errors("kl, fresh samples", m.mean, expected, m.standard_error));
    }
}

}  // namespace
}  // namespace hmcr::test
