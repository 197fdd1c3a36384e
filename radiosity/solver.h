// SPDX-License-Identifier: Apache-2.0
// solve(): a patch mesh in, an element hierarchy with radiosity out (docs/design.md §2, §3).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "common/progress.h"
#include "common/ranks.h"
#include "meshes/patch_mesh.h"
#include "meshes/view.h"
#include "radiosity/clusters.h"
#include "radiosity/hierarchy.h"
#include "radiosity/solver_options.h"

namespace hmcr {

// What a solve takes besides its settings: the scene's views, which importance = views solves
// for (the caller keeps them alive for the solve).
struct SolveInputs {
    std::span<const View> views;
};

struct IterationRecord {
    std::uint64_t rays = 0;
    Rgb unshot_before = Rgb::Zero();  // unshot power at the start of the iteration, W
    Rgb unshot_after = Rgb::Zero();
    std::size_t leaves_after = 0;
    double seconds = 0;
    bool frozen = false;                 // an iteration of the frozen pass of refine-then-freeze
    Rgb control_constant = Rgb::Zero();  // beta of the control variate (0: none), §3.11
};

// A solve's statistics, each with how refine-then-freeze joins its two passes' (§3.10): `both`
// adds the passes' values, `refining` takes the refining pass's (what built the mesh: the
// frozen pass refines nothing), `frozen` keeps the frozen pass's (the solution's own, or the
// same in both passes). Declared once, here, so that the join cannot leave a field out.
// clang-format off
#define HMCR_SOLVE_STATS(X)                                                                       \
    X(std::uint64_t, rays,               0,           both)     /* shot, both passes */           \
    X(std::uint64_t, refining_rays,      0,           refining) /* of them, those that refined */ \
    X(std::uint64_t, importance_rays,    0,           refining) /* view importance's, besides */  \
    X(std::uint64_t, oracle_calls,       0,           refining) /* link decisions */              \
    X(std::uint64_t, oracle_evaluations, 0,           refining) /* geometric factors computed */  \
    X(std::uint64_t, cache_hits,         0,           refining)                                   \
    X(std::uint64_t, lines_cast,         0,           refining)                                   \
    X(double,        oracle_seconds,     0,           refining) /* line factors, all threads */   \
    X(std::size_t,   cache_bytes,        0,           refining)                                   \
    X(std::size_t,   cache_capacity,     0,           refining)                                   \
    X(std::size_t,   cache_evictions,    0,           refining)                                   \
    X(double,        epsilon,            0,           refining) /* used (the oracle's default */  \
                                                                /* if not given) */               \
    X(int,           threads,            0,           frozen)   /* worker threads, each rank */   \
    X(int,           ranks,              1,           frozen)   /* MPI processes */               \
    X(std::size_t,   patches,            0,           frozen)   /* in the scene */                \
    X(std::size_t,   two_sided_patches,  0,           frozen)   /* with a back (§1.3) */          \
    X(Rgb,           emitted_power,      Rgb::Zero(), frozen)                                     \
    X(double,        total_area,         0,           frozen)   /* of the patches, m^2 */         \
    X(double,        max_emitted_power,  0,           frozen)   /* of a patch, brightest */       \
                                                                /* channel, W */                  \
    /* The power balance of the pass whose values the solution holds: the rays' power, what */   \
    /* left the scene, what back faces absorbed, what is left unshot. */                         \
    X(Rgb,           shot_power,         Rgb::Zero(), frozen)                                     \
    X(Rgb,           escaped_power,      Rgb::Zero(), frozen)                                     \
    X(Rgb,           back_face_power,    Rgb::Zero(), frozen)                                     \
    X(Rgb,           unshot_power,       Rgb::Zero(), frozen)                                     \
    /* leaves: the mesh's (what a budget counts), cluster_leaves of them clusters (§2.7); */     \
    /* faces: the hierarchy's leaves, one output cell each. */                                   \
    X(std::size_t,   elements,           0,           frozen)                                     \
    X(std::size_t,   leaves,             0,           frozen)                                     \
    X(std::size_t,   cluster_leaves,     0,           frozen)                                     \
    X(std::size_t,   faces,              0,           frozen)                                     \
    X(std::size_t,   hierarchy_bytes,    0,           frozen)                                     \
    X(double,        setup_seconds,      0,           both)                                       \
    X(double,        shooting_seconds,   0,           both)                                       \
    X(double,        push_pull_seconds,  0,           both)                                       \
    X(double,        total_seconds,      0,           both)                                       \
    X(double,        refining_seconds,   0,           refining) /* the refining pass's part */    \
    X(double,        importance_seconds, 0,           refining) /* view importance's part of */   \
                                                                /* refining_seconds */
// clang-format on

struct SolveStats {
    // Both passes' iterations, the refining pass's first.
    std::vector<IterationRecord> iterations;
#define HMCR_STATS_FIELD(type, name, zero, join) type name = zero;
    HMCR_SOLVE_STATS(HMCR_STATS_FIELD)
#undef HMCR_STATS_FIELD

    // A frozen pass's statistics joined with its refining pass's, by the table's rules; the
    // refining pass's iterations go first.
    void join_refining_pass(const SolveStats& refining);

    // Fraction of the shot power that hit back faces (a sign of flipped normals if > 1%).
    double back_face_fraction() const;
    // The iterations of the pass whose values the solution holds: the frozen pass's when the
    // mesh was refined first (they come last), else all.
    std::span<const IterationRecord> value_iterations() const;
};

struct Solution {
    std::unique_ptr<Hierarchy> hierarchy;
    // The clusters over hierarchy's sides with the mesh's open ones, for solving this mesh
    // again (none without clustering). Declared after `hierarchy`, which it points into.
    std::unique_ptr<ClusterTree> clusters;
    SolverOptions options;
    SolveStats stats;

    // Each side value's (2 * patch + side) cluster leaf, -1 where the side's own leaves are in
    // the mesh; empty without clustering. What the output calls ClusterId.
    const std::vector<std::int32_t>& cluster_of_side() const;
};

// One solve at the options' epsilon. The options are checked where they are read (validate,
// radiosity/solver_settings.h), once, and taken here as valid. Throws InputError on a scene
// without light. Reports the fraction of the rays shot to `progress`. `ranks` share every
// iteration's rays (rank_merge.h) and all return the same solution, bit for bit, as one process
// would. With options.refine_share below 1 it is a refining pass, then a frozen one
// (radiosity/solve_passes.h).
Solution solve(const PatchMesh& mesh, const SolverOptions& options, const SolveInputs& inputs = {},
               Progress& progress = no_progress(), const Ranks& ranks = Ranks::single());
// The same from the mesh's patches (build_patch_set), so that the mesh can be released before
// the rays are shot.
Solution solve(PatchSet patches, const SolverOptions& options, const SolveInputs& inputs = {},
               Progress& progress = no_progress(), const Ranks& ranks = Ranks::single());

// The same solve on a frozen mesh: the leaves of `shape` (a solution of the same mesh, its
// cluster leaves too), no refinement and no oracle. With many rays its error is the mesh's
// alone (studies' mesh error).
Solution solve_on_mesh(const PatchMesh& mesh, const SolverOptions& options, const Solution& shape,
                       Progress& progress = no_progress());

}  // namespace hmcr
