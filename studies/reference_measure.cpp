// SPDX-License-Identifier: Apache-2.0
#include "studies/reference_measure.h"

#include "studies/point_reference.h"
#include "studies/reference.h"
#include "viz/renderer.h"
#include "viz/solution_file.h"

namespace hmcr {

LoadedReference load_reference(const std::filesystem::path& dir, const Scene& scene) {
    LoadedReference ref;
    ref.kind = reference_kind(dir);
    switch (ref.kind) {
        case ReferenceKind::mesh:
            ref.mesh = read_solution(dir / "reference.vtp", scene).mesh;
            ref.resolution = ReferenceResolution::of_mesh(*ref.mesh);
            ref.error_options = reflected_error_options(scene.mesh);
            break;
        case ReferenceKind::points:
            ref.points = point_target(read_reference_points(dir, scene), diffuse_patch_set(scene));
            ref.resolution = ReferenceResolution::of_points(ref.points->points);
            break;
        case ReferenceKind::traced:
            break;
    }
    for (const auto& [name, view] : read_reference_views(dir, scene)) {
        ref.exposure[name] = view.exposure;
        ref.images[name] = quantise(view.image, view.exposure);
    }
    return ref;
}

SolutionErrors measure_solution(const LoadedReference& ref, const ShadedMesh& solution,
                                const Scene& scene, int samples_per_axis) {
    SolutionErrors out;
    if (!ref.resolution.empty()) out.finer_share = ref.resolution.finer_share(solution);
    const ShadedTracer tracer(solution);
    const RenderOptions render_options{samples_per_axis};
    for (View v : scene.views) {
        const Image8& image = ref.images.at(v.name);
        v.width = image.width;  // a traced reference may be smaller than the view
        v.height = image.height;
        Image8 mine = quantise(render(tracer, v, render_options), ref.exposure.at(v.name));
        out.views[v.name] = image_errors(mine, image);
        out.images[v.name] = std::move(mine);
    }
    if (ref.mesh) {
        out.object = object_space_error(tracer, solution, *ref.mesh, ref.error_options);
    } else if (ref.points) {
        out.object = point_object_error(tracer, solution, *ref.points);
    } else {
        out.object.relative_l2 = std::numeric_limits<double>::quiet_NaN();
    }
    return out;
}

}  // namespace hmcr
