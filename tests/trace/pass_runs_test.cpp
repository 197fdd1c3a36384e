// SPDX-License-Identifier: Apache-2.0
// The passes of Blender Cycles' scheme (trace/pass_runs.h), checked against its rule from the
// outside: each pixel's samples are traced again batch by batch and judged by the criterion, and
// a pixel went on after a pass exactly when it or one of its 8 neighbours still running was
// unconverged.
#include "trace/pass_runs.h"

#include <gtest/gtest.h>

#include "meshes/scene.h"
#include "rays/camera.h"
#include "trace/criteria/registry.h"
#include "trace/trace_image.h"

namespace hmcr::test::pass_runs {
namespace {

TEST(PassRuns, APixelGoesOnWhileItOrANeighbourIsUnconverged) {
    const Scene scene = load_scene("cornell");
    const PathTracer tracer(build_patch_set(scene.mesh), {});
    View v = find_view(scene, "camera");
    v.width = v.height = 12;
    const Criterion& criterion = *criterion_registry().find("half-difference");
    TraceOptions o;
    o.sampler = &criterion;
    o.spp = 24;
    o.seed = 9;
    const TraceResult r = trace_image(tracer, v, o);
    ASSERT_FALSE(std::isnan(r.threshold));
    const std::uint32_t most = max_samples_per_pixel(o);

    // Every pixel's value after each of its batches, from its samples traced again.
    const Camera camera = make_camera(v);
    const PixelTracer pixels(tracer, camera, o.seed);
    const int w = v.width, h = v.height;
    std::vector<std::vector<double>> values(std::size_t(w * h));
    for (int i = 0; i < w * h; ++i) {
        std::vector<PixelSample> samples;
        for (std::uint32_t first = 0; first < r.samples[std::size_t(i)]; first += kBatchSize) {
            for (const TracedSample& t :
                 trace_pixel_batch(pixels, i % w, i / w, first, std::min(first + kBatchSize, most)))
                samples.push_back(store(t.sample).expand());
            values[std::size_t(i)].push_back(criterion.value(samples, 1.0));
        }
    }
    // After pass k the pixels that took it (k + 1 batches or more) are running; p goes on iff it
    // is below its most and p or a running neighbour was unconverged.
    std::size_t went_on = 0;
    for (int i = 0; i < w * h; ++i) {
        const std::size_t batches = values[std::size_t(i)].size();
        for (std::size_t k = 0; k < batches; ++k) {
            bool unconverged = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = i % w + dx, y = i / w + dy;
                    if (x < 0 || y < 0 || x >= w || y >= h) continue;
                    const auto& q = values[std::size_t(y * w + x)];
                    if (q.size() > k && q[k] > r.threshold) unconverged = true;
                }
            const bool below_most = kBatchSize * (k + 1) < most;
            EXPECT_EQ(k + 1 < batches, below_most && unconverged) << "pixel " << i << " pass " << k;
            went_on += k + 1 < batches ? 1 : 0;
        }
    }
    EXPECT_GT(went_on, 0u);
}

}  // namespace
}  // namespace hmcr::test::pass_runs
