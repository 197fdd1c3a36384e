// SPDX-License-Identifier: Apache-2.0
// The passes of a solve (docs/design.md §3.10): what solve() and the budget search run, each
// pass given its rays and threshold by its caller, derived once from the options, so that no
// pass edits the options it was given. Not an entry point: solver.h and budget_search.h are.
#pragma once

#include <cstdint>
#include <memory>

#include "radiosity/solver.h"

namespace hmcr {

class EmbreeScene;      // rays/embree_scene.h
class ShootingBuffers;  // radiosity/shooting.h
struct ViewImportance;  // radiosity/view_importance.h

// What a refining pass (refine_pass) leaves for its frozen pass and for a budget search's next
// probe, which shoot in the same patches: the Embree scene, the buffers the rays' batches pass
// through, whose pages are then faulted in once a solve instead of once a pass, and the view
// importance once solved (it depends on the scene, the views, the seed and the rays alone).
struct ShootingSetup {
    std::shared_ptr<const EmbreeScene> scene;
    std::shared_ptr<ShootingBuffers> buffers;
    std::shared_ptr<const ViewImportance> importance;
};

// What a pass shoots besides its options: the refinement threshold (the oracle's default where
// the options give none) and the pass's share of the rays.
struct Pass {
    double epsilon = 0;
    std::uint64_t rays = 0;
};

// Refine-then-freeze's two passes: the refining pass's share of the rays (at least one), and
// the rest for the frozen pass, which has none (rays 0) where the solve does not refine then
// freeze (refine_share 1, a fixed mesh, or a single ray).
struct Passes {
    Pass refining, frozen;
};
Passes passes_of(const SolverOptions& options);

// All of a solve's rays in one pass: a frozen mesh's.
Pass whole_solve(const SolverOptions& options);

// The refined solve of `patches` (or the fixed mesh of uniform_max_area) with `pass`'s rays,
// what a budget search probes. Shoots with `shooting`'s scene, buffers and view importance
// where it has them (an earlier probe's, of these patches), and leaves its own in it.
Solution refine_pass(PatchSet patches, const SolverOptions& options, const Pass& pass,
                     const SolveInputs& inputs, ShootingSetup& shooting,
                     Progress& progress = no_progress(), const Ranks& ranks = Ranks::single());

// The refining pass's leaves solved again from scratch with `pass`'s rays, in its tree, and
// shooting with the refining pass's `shooting`, which it then lets go; returns that solution,
// with the refining pass's mesh statistics and both passes' iterations. With no rays (a solve
// that does not freeze) it returns `refined` as it is.
Solution freeze_pass(Solution refined, const Pass& pass, ShootingSetup shooting,
                     Progress& progress = no_progress(), const Ranks& ranks = Ranks::single());

}  // namespace hmcr
