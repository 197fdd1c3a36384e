// SPDX-License-Identifier: Apache-2.0
// The papers' two passes (trace/map_allocation.h): the allocation in proportion to the map, its
// cap and its total; the image reusing the first pass is the uniform image of each pixel's
// count, and the fresh one is traced from the fresh streams at the same counts.
#include "trace/map_allocation.h"

#include <gtest/gtest.h>

#include <numeric>

#include "meshes/scene.h"
#include "rays/rng.h"
#include "tests/support/image_checks.h"
#include "trace/criteria/registry.h"
#include "trace/pixel_runs.h"
#include "trace/trace_image.h"

namespace hmcr::test::map_allocation {
namespace {

TEST(MapAllocation, SharesTheBudgetInProportionToTheMap) {
    // 4 pixels at 13 spp: 20 samples beyond the first 8 each, shared 1 : 2 : 3 : 4
    EXPECT_EQ(allocate_from_map(std::vector<double>{1, 2, 3, 4}, 13, 8, 100),
              (std::vector<std::uint32_t>{10, 12, 14, 16}));
    // a map of zeros (or a uniform one) is uniform sampling
    EXPECT_EQ(allocate_from_map(std::vector<double>{0, 0, 0}, 16, 8, 64),
              (std::vector<std::uint32_t>{16, 16, 16}));
    EXPECT_EQ(allocate_from_map(std::vector<double>{5, 5}, 20, 8, 64),
              (std::vector<std::uint32_t>{20, 20}));
}

TEST(MapAllocation, CapsAPixelAtItsMostAndSharesTheRest) {
    // 12 samples beyond the first: the bright pixel reaches its cap of 16, the other takes 4
    EXPECT_EQ(allocate_from_map(std::vector<double>{1, 100}, 14, 8, 16),
              (std::vector<std::uint32_t>{12, 16}));
    // every positive pixel at the cap: the pixels of value 0 share the rest evenly
    EXPECT_EQ(allocate_from_map(std::vector<double>{0, 0, 5}, 14, 8, 16),
              (std::vector<std::uint32_t>{13, 13, 16}));
}

TEST(MapAllocation, KeepsTheTotalAndTheBounds) {
    Rng rng(1, 2);
    std::vector<double> values(1000);
    for (double& v : values) v = rng.uniform() < 0.3 ? 0 : -std::log1p(-rng.uniform());
    for (const double spp : {8.0, 9.5, 16.0, 60.0, 127.0}) {
        const auto counts = allocate_from_map(values, spp, 8, 128);
        const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
        EXPECT_NEAR(total, spp * double(values.size()), 1.0) << spp;
        for (std::uint32_t n : counts) {
            EXPECT_GE(n, 8u);
            EXPECT_LE(n, 128u);
        }
    }
    EXPECT_THROW(allocate_from_map(values, 7, 8, 128), std::invalid_argument);
    EXPECT_THROW(allocate_from_map(values, 129, 8, 128), std::invalid_argument);
    EXPECT_THROW(allocate_from_map(std::vector<double>{1, -1}, 16, 8, 128), std::invalid_argument);
}

// The Cornell box's camera at 24 x 24 pixels.
struct Cornell {
    Scene scene = load_scene("cornell");
    PathTracer tracer{build_patch_set(scene.mesh), {}};
    View view = [this] {
        View v = find_view(scene, "camera");
        v.width = v.height = 24;
        return v;
    }();
};

TraceOptions map_options(const char* sampler, double spp, bool fresh) {
    TraceOptions o;
    o.sampler = criterion_registry().find(sampler);
    o.spp = spp;
    o.seed = 4;
    o.allocation = Allocation::map;
    o.fresh = fresh;
    return o;
}

// Reusing the first pass, a pixel of n samples is the mean of the first n samples of its
// uniform stream: the image a uniform run of each pixel's count gives (up to the order of the
// sums), for a batch criterion and a quadtree one.
TEST(MapAllocation, TheReusedImageIsTheUniformImageOfEachPixelsCount) {
    const Cornell c;
    for (const char* sampler : {"srhe", "entropy", "half-difference"}) {
        const TraceResult r = trace_image(c.tracer, c.view, map_options(sampler, 20, false));
        EXPECT_NEAR(r.counts().mean, 20, 1.0 / 576) << sampler;
        EXPECT_GE(r.counts().min, 8u);
        EXPECT_EQ(r.rays, r.rays_traced);
        EXPECT_TRUE(std::isnan(r.threshold));
        const Camera camera = make_camera(c.view);
        const PixelTracer pixels(c.tracer, camera, 4);
        std::uint64_t rays = 0;
        const Image uniform = fresh_image(pixels, r.samples, rays);
        EXPECT_EQ(rays, r.rays) << sampler;
        for (std::size_t i = 0; i < uniform.pixels.size(); ++i)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(r.image.pixels[i][k], uniform.pixels[i][k],
                            1e-12 * (1 + uniform.pixels[i][k]))
                    << sampler << " pixel " << i;
    }
}

// Without reuse the image is traced again from the fresh streams (the seed with bit 62 flipped,
// docs/design.md §9.1) at the same counts; the first pass's rays are counted too.
TEST(MapAllocation, TheFreshImageIsTracedAgainAtTheSameCounts) {
    const Cornell c;
    const TraceResult reused = trace_image(c.tracer, c.view, map_options("kl", 24, false));
    const TraceResult fresh = trace_image(c.tracer, c.view, map_options("kl", 24, true));
    EXPECT_EQ(fresh.samples, reused.samples);
    const Camera camera = make_camera(c.view);
    const PixelTracer pixels(c.tracer, camera, 4 ^ (std::uint64_t(1) << 62));
    std::uint64_t rays = 0;
    EXPECT_TRUE(identical(fresh.image, fresh_image(pixels, fresh.samples, rays)));
    EXPECT_EQ(fresh.rays, rays);
    // the first pass: 8 samples of every pixel's own stream
    const PixelTracer own(c.tracer, camera, 4);
    std::uint64_t first_rays = 0;
    fresh_image(own, std::vector<std::uint32_t>(fresh.samples.size(), 8), first_rays);
    EXPECT_EQ(fresh.rays_traced, rays + first_rays);
}

}  // namespace
}  // namespace hmcr::test::map_allocation
