// SPDX-License-Identifier: Apache-2.0
// A solution as ParaView reads it (docs/design.md §5): the hierarchy's leaves as a conforming
// Gouraud mesh, written to a .vtp with the run's metadata. The one way solve, reference and
// study write their solutions.
#pragma once

#include <filesystem>

#include "meshes/scene.h"
#include "radiosity/shaded_mesh.h"
#include "radiosity/solver.h"
#include "viz/vtk_export.h"

namespace hmcr {

// What a solution file records of its scene, taken before `hmcr solve` releases the mesh.
struct SceneIdentity {
    std::string name;
    std::size_t patches = 0;
    std::string geometry_hash;  // geometry_hash() of the mesh
};
SceneIdentity scene_identity(const Scene& scene);

// The metadata of a solve of the scene: its oracle ("uniform" for a fixed uniform mesh, which
// has no epsilon and no lines), epsilon, lines, rays, seed, leaves, iterations, and the scene's
// name, patch count and geometry hash. time_value is ParaView's time of the file (a study puts
// the budget there, to step through budgets).
VtpMetadata vtp_metadata(const Solution& solution, const SceneIdentity& scene, double time_value);

// The shaded leaves of the solution (patches meeting at crease_degrees or more are not
// blended).
ShadedMesh shade(const Solution& solution, double crease_degrees);

// Writes the shaded mesh of the solution atomically.
void write_solution(const std::filesystem::path& vtp, const ShadedMesh& shaded,
                    const Solution& solution, const SceneIdentity& scene, double time_value);
// shade() then write_solution(); returns the mesh for whoever measures it next, its radiosities
// rounded to single precision as the file holds them.
ShadedMesh write_solution(const std::filesystem::path& vtp, const Solution& solution,
                          const Scene& scene, double crease_degrees, double time_value);

// The mesh as its file holds it, radiosities rounded to single precision: what a study measures,
// so that it measures what `hmcr error` of the file measures.
ShadedMesh as_stored(ShadedMesh mesh);

// A solution file read back: its mesh and its metadata (viz/vtk_import.h checks both).
struct SolutionFile {
    ShadedMesh mesh;
    VtpMetadata meta;
};
SolutionFile read_solution(const std::filesystem::path& vtp);
// The same, refused (InputError naming the file) unless it was solved for this scene.
SolutionFile read_solution(const std::filesystem::path& vtp, const Scene& scene);

}  // namespace hmcr
