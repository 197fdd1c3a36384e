// SPDX-License-Identifier: Apache-2.0
#include "tests/support/information.h"

#include <cmath>

#include "meshes/scene.h"
#include "tests/support/analytic.h"
#include "tests/support/test_scenes.h"

namespace hmcr::test {

double plug_in_bias_bound(const PatchSet& set, const ChannelSamples& samples) {
    const double k = double(set.patches.size());
    double bound = 0;
    for (std::size_t i = 0; i < set.patches.size(); ++i) {
        const double n = double(samples.targets(i).size());
        if (n > 0) bound += set.patches[i].area / set.total_area * std::log2(1 + (k - 1) / n);
    }
    return bound;
}

namespace {

// The share of open rays in each batch (rays of one global line are not independent, so the
// error comes from the batches, not from a binomial count).
Estimate open_share(const ChannelSamples& samples) {
    std::vector<double> share;
    for (std::uint32_t b = 0; b < samples.batches; ++b) {
        double open = 0, all = 0;
        for (std::size_t i = 0; i < samples.patches(); ++i) {
            for (std::uint32_t t : samples.targets(i, b)) open += t == ChannelSamples::kNoPatch;
            all += double(samples.targets(i, b).size());
        }
        share.push_back(open / all);
    }
    return estimate_mean(share);
}

}  // namespace

MeasuredChannel measure_channel(const PatchSet& set, const LineOptions& options) {
    const EmbreeScene scene(set.patches);
    const ChannelSamples samples = trace_lines(set, scene, options);
    return {scene_information(set, samples, options.method), plug_in_bias_bound(set, samples),
            open_share(samples)};
}

EmptyCube empty_cube() {
    EmptyCube c;
    c.opposite = parallel_rectangles(1, 1, 1);
    c.adjacent = perpendicular_rectangles(1, 1, 1);
    const auto plogp = [](double p) { return p * std::log2(p); };
    c.h_p = std::log2(6.0);
    c.h_s = -(plogp(c.opposite) + 4 * plogp(c.adjacent));  // every row alike
    c.i_s = c.h_p - c.h_s;
    return c;
}

PatchSet cube_patches(double size, int n) {
    return build_patch_set(make_patch_mesh(
        inward_box(Vec3::Zero(), Vec3::Constant(size), n, Rgb::Constant(0.5), Rgb::Zero())));
}

PatchSet cornell_patches() { return build_patch_set(load_scene("cornell").mesh); }

}  // namespace hmcr::test
