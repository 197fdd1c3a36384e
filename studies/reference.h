// SPDX-License-Identifier: Apache-2.0
// Converged references (docs/design.md §6): a fixed uniform mesh solved with many rays, twice with
// different seeds, so that the reference states its own convergence in the study's metrics.
//
// On disk (`hmcr reference SCENE -o DIR`):
//   DIR/reference.vtp          the solution of the first seed (a normal hmcr solution)
//   DIR/reference.json         its run summary plus "reference": options, the exposure of every
//                              view, and the convergence report (second seed vs first)
//   DIR/views/VIEW.pfm         the first seed's image of every view, linear radiance
//   DIR/views/VIEW.png         the same, 8-bit sRGB at the view's fixed exposure
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/output_set.h"
#include "common/progress.h"
#include "image/image.h"
#include "meshes/scene.h"
#include "radiosity/shaded_mesh.h"
#include "radiosity/solver.h"
#include "radiosity/truncation.h"
#include "studies/metrics.h"
#include "studies/object_space_error.h"

namespace hmcr {

// The check of a mesh reference's discretisation (check_size): by default at most this many
// points, four a uniform element, with paths for about a tenth of the solve's rays.
inline constexpr std::uint64_t kMostCheckPoints = 20'000;

// The solver settings a mesh reference does not take: its uniform mesh has no oracle, no
// refinement limits and no clusters.
inline const std::set<std::string> kNotReferenceSettings{
    "oracle",   "epsilon",     "lines",        "min_area",   "max_depth",
    "cache_mb", "link_weight", "refine_share", "clustering", "importance"};
// The settings a scene file's "solver" object does not set for a reference: its own.
inline const std::set<std::string> kReferenceOwnSettings{"rays", "seed"};

struct ReferenceOptions {
    double max_area = 1e-4;  // m^2: every patch cut to elements no larger
    // The two solves: rays per seed, the first seed (the second is seed + 1), threads, stop.
    // The mesh settings (oracle, epsilon, limits) are the uniform mesh's own.
    SolverOptions solver = [] {
        SolverOptions s;
        s.rays = 200'000'000;
        // A reference stops when what is left unshot would add at most about 1e-4 of the
        // light (radiosity/truncation.h reports it); the solver's 0.01 left 1.1% of the red
        // power unshot on the Cornell box, its later bounces missing from every study.
        s.stop = 1e-4;
        return s;
    }();
    int samples_per_axis = 2;  // supersampling of the view images
    double crease_degrees = kCreaseDegrees;
    // The check of the mesh's own discretisation: the first seed's solution measured against
    // this many stratified points (studies/point_error.h); 0 for none; none given: check_size's.
    std::optional<std::uint64_t> check_points;
};

// The points and paths a point of the check of a reference of `elements` uniform elements
// takes (docs/design.md §6.2).
struct CheckSize {
    std::uint64_t points = 0, paths = 0;
};
CheckSize check_size(const ReferenceOptions& options, std::uint64_t elements);

struct ViewImage {
    Image image;      // linear radiance
    double exposure;  // fixed from this image for every image of a study
};

struct Reference {
    Solution solution;  // first seed
    ShadedMesh mesh;
    std::map<std::string, ViewImage> views;
    // Convergence: the second seed's solution measured against the first, as a study would.
    ObjectError object_error;
    std::map<std::string, ImageErrors> view_errors;
    // What stopping left out (first seed), next to the seeds' difference in the same terms:
    // |reflected power of seed 2 - seed 1| / reflected power of seed 1, per channel.
    TruncationBias truncation;
    Rgb seed_difference = Rgb::Zero();
    // The first seed's solution against the check points: its discretisation error and noise
    // (samples 0 when not checked).
    ObjectError discretisation;
    std::uint64_t check_paths = 0;
    double seconds = 0;
};

// Each solve, the comparison and each view's image are stages of `progress`.
Reference compute_reference(const Scene& scene, const ReferenceOptions& options,
                            Progress& progress = no_progress(),
                            const Ranks& ranks = Ranks::single());

// Object-space error options relative to the reflected radiosity B - E of the scene's patches
// (studies/object_space_error.h): how references and studies compare solutions.
ObjectErrorOptions reflected_error_options(const PatchMesh& mesh);

// The scene's file as references record it (reference.json's "scene_file"), absolute, so that
// `hmcr error` finds the scene from any folder; "" for a scene of no file, whose reference does
// not record one (`hmcr error` then needs --scene).
std::string scene_file(const Scene& scene);

// The files write_reference writes for this scene.
std::vector<std::filesystem::path> reference_files(const std::filesystem::path& dir,
                                                   const Scene& scene);

// Writes the folder described above into `out`, an OutputSet of reference_files(dir, scene)
// (common/output_set.h), which the caller commits.
void write_reference(OutputSet& out, const std::filesystem::path& dir, const Scene& scene,
                     const Reference& reference, const ReferenceOptions& options,
                     nlohmann::json summary);

// The exposure fixed for each view in a reference folder's reference.json; throws
// InputError naming the file when it is missing or malformed.
std::map<std::string, double> read_reference_exposures(const std::filesystem::path& dir);

}  // namespace hmcr
