#include "tests/support/information.h"

#include <cmath>

#include "meshes/scene.h"
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

MeasuredChannel measure_channel(const PatchSet& set, const LineOptions& options) {
    const EmbreeScene scene(set.patches);
    const ChannelSamples samples = trace_lines(set, scene, options);
    return {scene_information(set, samples, options.method), plug_in_bias_bound(set, samples)};
}

PatchSet cube_patches(double size, int n) {
    return build_patch_set(make_patch_mesh(
        inward_box(Vec3::Zero(), Vec3::Constant(size), n, Rgb::Constant(0.5), Rgb::Zero())));
}

PatchSet cornell_patches() { return build_patch_set(load_scene("cornell").mesh); }

}  // namespace hmcr::test
