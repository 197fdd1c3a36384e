// SPDX-License-Identifier: Apache-2.0
// MGF, the Materials and Geometry Format (Ward, LBNL, 1995; version 2.0 of the specification):
// RenderPark's and Radiance's scene format. Written from the public specification.
//
// Read: o, xf (-t -rx -ry -rz -s -mx -my -mz -i -a), i (relative to the including file, with a
// transformation), c with cxy, cspec, cct and cmix, m with rd, ed and sides, v with p and n, f
// (seams included), and the surfaces sph, cyl, cone, ring, torus and prism tessellated as
// meshes/mgf_shapes.h says. Colours become RGB as meshes/mgf_color.h and mgf_color_fit.h say; `ed`
// (lm/m^2) becomes the emitted radiosity E with that luminance, so an MGF scene's radiosity is in
// lm/m^2 where an OBJ scene's is in W/m^2. `rs` is the specular part only the path tracer
// reflects (docs/design.md §1.2); ts, td, ir and ies are ignored with one warning naming them. A
// material's `sides` (2 unless it says 1, as the specification has it) is kept with it for the
// loader (meshes/material_sides.h): a two-sided material's faces get a back of the same material.
#pragma once

#include <cstdint>
#include <filesystem>

#include "meshes/polygon_soup.h"

namespace hmcr {

struct MgfOptions {
    int curve_segments = 24;  // segments per full circle of a curved surface
    // Statements and array instances run at most, arrays and includes expanded: a file of a
    // few lines can ask for 10^18 instances. 10^7 is a few seconds of refusing, and over a
    // thousand times what RenderPark's largest scene (soda, 7,134) runs.
    std::uint64_t max_statements = 10'000'000;
    // Arrays are counted before they run (meshes/mgf_polygon_count.h): one whose polygons would
    // pass this is refused before it makes any.
    std::size_t max_polygons = 50'000'000;
    // Transformations (xf blocks) and includes nested around a statement, counted together:
    // each level is a few hundred bytes of the stack, and a file of 20,000 levels overflowed it.
    // RenderPark's scenes nest a handful.
    int max_nesting = 1000;
};

// The polygons and materials of an MGF file and the files it includes. Throws InputError
// "file:line: why" on anything that is not valid MGF or cannot be read.
PolygonSoup read_mgf(const std::filesystem::path& mgf, const MgfOptions& options = {});

}  // namespace hmcr
