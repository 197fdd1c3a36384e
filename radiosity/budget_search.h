// Solving to an element budget (docs/design.md §6.1): epsilon searched for on log epsilon
// until the leaf count is within a tolerance of the target, every probe a refined solve with the
// same seed (the refining pass alone under refine-then-freeze, the accepted one then frozen).
#pragma once

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "common/error.h"
#include "radiosity/solver.h"

namespace hmcr {

struct BudgetOptions {
    std::size_t leaves = 0;   // the target leaf count
    double tolerance = 0.01;  // accepted relative distance to the target
    int max_probes = 40;      // solves before giving up
};

struct BudgetProbe {
    double epsilon = 0;
    std::size_t leaves = 0;
    double seconds = 0;
};
// {"epsilon", "leaves", "seconds"}: how run summaries and study cells store a probe.
void to_json(nlohmann::json& j, const BudgetProbe& p);

struct BudgetResult {
    Solution solution;  // the accepted probe's solve
    std::vector<BudgetProbe> probes;
};

// The budget cannot be reached with these settings: a result of a study cell, an error of a
// solve.
class BudgetNotReached : public InputError {
public:
    using InputError::InputError;
};

// Starts from options.epsilon (or the oracle's default). Each probe is a stage of `progress`,
// and its result a note. Throws BudgetNotReached with a one-line explanation when the budget
// cannot be reached: below the patch count, above what the area/depth limits and the rays
// allow, or not within the tolerance after max_probes; InputError on bad options. `ranks`
// share each probe's solve (solver.h).
BudgetResult solve_for_budget(const PatchMesh& mesh, const SolverOptions& options,
                              const BudgetOptions& budget, Progress& progress = no_progress(),
                              const Ranks& ranks = Ranks::single());

// Throws InputError on a tolerance outside (0, 1); a budget of 0 leaves means none.
void validate(const BudgetOptions& budget);

// One solve at epsilon when budget.leaves is 0, else a budget search: what `hmcr solve` asks.
// A solve at epsilon needs the mesh only for its patches (build_patch_set), which keep what the
// output needs of it, so the mesh is released before the rays are shot; a budget search keeps
// it, since every probe builds its patches from it.
BudgetResult solve_mesh(PatchMesh& mesh, const SolverOptions& options, const BudgetOptions& budget,
                        Progress& progress = no_progress(), const Ranks& ranks = Ranks::single());

}  // namespace hmcr
