// SPDX-License-Identifier: Apache-2.0
// A solution measured against a reference of any kind (docs/design.md §6.5, §6.6, §6.9): what
// a study does to each cell and `hmcr error` to any solution. The reference is loaded once:
// its mesh (studies/reference.h) or its points (studies/point_reference.h) for the object
// error, its resolution (studies/reference_resolution.h), and every view's image at its fixed
// exposure. A traced reference (studies/traced_reference.h) has the images alone: the object
// error is not measured (NaN).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "image/image.h"
#include "meshes/scene.h"
#include "radiosity/shaded_mesh.h"
#include "studies/metrics.h"
#include "studies/object_space_error.h"
#include "studies/point_error.h"
#include "studies/reference_resolution.h"
#include "studies/traced_reference.h"
#include "viz/shaded_tracer.h"

namespace hmcr {

struct LoadedReference {
    ReferenceKind kind = ReferenceKind::mesh;
    std::optional<ShadedMesh> mesh;
    std::optional<PointTarget> points;
    ReferenceResolution resolution;
    ObjectErrorOptions error_options;      // the mesh reference's: relative to B - E
    std::map<std::string, Image8> images;  // quantised with the view's exposure
    std::map<std::string, double> exposure;
};

// Throws InputError naming the file that is missing, malformed or made for another scene.
LoadedReference load_reference(const std::filesystem::path& dir, const Scene& scene);

struct SolutionErrors {
    std::map<std::string, Image8> images;  // the solution's, at the reference's size and exposure
    std::map<std::string, ImageErrors> views;
    ObjectError object;
    // The share of the solution's area in leaves finer than the reference resolves (NaN for a
    // traced reference).
    double finer_share = std::numeric_limits<double>::quiet_NaN();
};

// Renders every view of the scene at the reference image's size with n x n rays a pixel and
// measures images and object error.
SolutionErrors measure_solution(const LoadedReference& reference, const ShadedMesh& solution,
                                const Scene& scene, int samples_per_axis);

}  // namespace hmcr
