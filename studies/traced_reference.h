// SPDX-License-Identifier: Apache-2.0
// Traced references: every view of a scene path-traced with the uniform sampler at
// many samples per pixel, an independent solution of the same light transport against which
// sampling studies (studies/sampling_study.h) measure adaptive images. `hmcr trace-reference`
// writes one; each view's image is the one `hmcr trace --sampler uniform --spp N` gives.
//
// On disk (DIR):
//   DIR/reference.json   {"command", "hmcr_version", "reference": {"kind": "traced", "scene",
//                        "sampler": "uniform", "spp", "seed", "path", "seconds",
//                        "views": {VIEW: {"exposure", "width", "height", "rays", "seconds"}}}}
//   DIR/views/VIEW.pfm   linear radiance
//   DIR/views/VIEW.png   8-bit sRGB at the view's exposure
// The exposure of a view maps the mean luminance of its non-background pixels to middle grey
// (viz/renderer.h, exposure_from); "reference" / "views" / VIEW / "exposure" is where a
// radiosity reference (studies/reference.h) keeps it too, so `render --reference`,
// `trace --reference` and read_reference_exposures take either kind of folder.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/output_set.h"
#include "common/progress.h"
#include "image/image.h"
#include "meshes/scene.h"
#include "trace/trace_image.h"

namespace hmcr {

struct TracedView {
    Image image;  // linear radiance
    double exposure = 1;
    std::uint64_t rays = 0;
    double seconds = 0;
};

struct TracedReference {
    std::map<std::string, TracedView> views;
    double seconds = 0;
};

// Traces every view (each a stage of `progress`) with options.sampler forced to uniform.
TracedReference compute_traced_reference(const Scene& scene, const std::vector<View>& views,
                                         TraceOptions options, Progress& progress = no_progress());

// Every view traced by `tracer` with `options` (the sampler forced to uniform), each a stage of
// `progress`, with the exposure fixed from its image.
std::map<std::string, TracedView> trace_views(const PathTracer& tracer,
                                              const std::vector<View>& views, TraceOptions options,
                                              Progress& progress);

// views/VIEW.pfm and .png of each view into `out`; returns reference.json's "views" object
// (each view's exposure, size, rays and seconds).
nlohmann::json write_view_images(OutputSet& out, const std::filesystem::path& dir,
                                 const std::map<std::string, TracedView>& views);

// Every file write_traced_reference writes into `dir`, for the checks before the work.
std::vector<std::filesystem::path> traced_reference_files(const std::filesystem::path& dir,
                                                          const Scene& scene);

// Writes the folder described above into `out`, an OutputSet of traced_reference_files(dir,
// scene) (common/output_set.h), which the caller commits; `command` is the invocation.
void write_traced_reference(OutputSet& out, const std::filesystem::path& dir, const Scene& scene,
                            const TracedReference& reference, const TraceOptions& options,
                            const std::string& command);

// What a reference folder holds, from its reference.json's "kind": a radiosity reference's mesh
// (studies/reference.h, no kind), a traced one's images alone ("traced"), or a point reference's
// points and images ("points", studies/point_reference.h).
enum class ReferenceKind { mesh, traced, points };
ReferenceKind reference_kind(const std::filesystem::path& dir);

// Every view of the scene read back from a reference folder of either kind: its linear image
// (views/VIEW.pfm) and its exposure. Throws InputError naming the file when one is missing.
std::map<std::string, TracedView> read_reference_views(const std::filesystem::path& dir,
                                                       const Scene& scene);

}  // namespace hmcr
