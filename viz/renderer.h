// SPDX-License-Identifier: Apache-2.0
// hmcr's own image renderer (docs/design.md §6): Embree primary rays on a solution's Gouraud mesh,
// barycentric interpolation of the vertex radiosity, radiance L = B / pi (Lambertian surfaces).
//
// Camera: the pinhole of rays/camera.h; pixel (x, y), y counted from the top row, covers
// [x, x + 1] x [y, y + 1] on the image plane. With n = samples_per_axis, a pixel is the
// mean of n x n rays through the fixed sub-pixel points ((i + 1/2) / n, (j + 1/2) / n): a
// deterministic stratified box filter, so images are reproducible and identical for any number
// of threads. Rays that hit nothing contribute 0 (the background).
#pragma once

#include <string>

#include "image/image.h"
#include "meshes/scene.h"
#include "radiosity/shaded_mesh.h"
#include "viz/shaded_tracer.h"

namespace hmcr {

struct RenderOptions {
    int samples_per_axis = 1;  // supersampling: n x n stratified rays per pixel, n >= 1

    std::string to_string() const;
};

// The linear radiance image of the mesh seen from the view. Throws std::invalid_argument on a
// bad view (size, fov outside (0, 180), position at look_at, up along the viewing direction) or
// bad options. Rows are rendered in parallel with TBB.
Image render(const ShadedMesh& mesh, const View& view, const RenderOptions& options = {});
// The same with a tracer built once for several views of one mesh.
Image render(const ShadedTracer& tracer, const View& view, const RenderOptions& options = {});

// The image (of the view's size) with the boundaries of the mesh's cells, its leaf elements,
// drawn over it in `ink`: a pixel is on one where the ray through its centre meets another cell
// than the ray through its right or lower neighbour's, or where one of the two meets nothing.
Image8 draw_cell_edges(const ShadedTracer& tracer, const View& view, Image8 image, Srgb8 ink);

// The fixed exposure a study takes from its reference image and applies to every image of the
// study: it maps the mean luminance of the reference's non-background pixels to middle grey
// (kMiddleGrey = 0.18), as auto_exposure does for meshes. Non-background means a luminance
// above zero: background pixels are exactly 0, and a lit radiosity scene has no exactly black
// surface, so the test needs no mask and works on an image read back from a PFM file. Returns 1
// for an all-black image.
double exposure_from(const Image& reference);

}  // namespace hmcr
