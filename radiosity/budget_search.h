// SPDX-License-Identifier: Apache-2.0
// Solving to an element budget (docs/design.md §6.1): epsilon searched for on log epsilon
// until the leaf count is within a tolerance of the target, every probe a refined solve with the
// same seed (the refining pass alone under refine-then-freeze, the accepted one then frozen).
#pragma once

#include <cstddef>
#include <map>
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
    double seconds = 0;  // 0 for a known probe
    bool known = false;  // its leaf count was known (KnownProbes), not solved again
};
// {"epsilon", "leaves", "seconds"}: how run summaries and study cells store a probe. Whether it
// was known is not stored: that depends on which cells a rank solved before, and like the
// seconds it is how the work was done, where everything else a study stores is the same for
// any rank count.
void to_json(nlohmann::json& j, const BudgetProbe& p);

struct BudgetResult {
    Solution solution;  // the accepted probe's solve
    std::vector<BudgetProbe> probes;
};

// The leaf counts of the probes solved so far with the same options (the same seed, rays and
// oracle among them) for other budgets, by epsilon: a study's searches for one oracle and seed
// at several budgets start alike. A solve gives the same bits every time, so a search that
// comes to a known epsilon takes its leaf count instead of solving again, unless that probe is
// the one it accepts, whose solve it needs.
using KnownProbes = std::map<double, std::size_t>;

// The budget cannot be reached with these settings: a result of a study cell, an error of a
// solve.
class BudgetNotReached : public InputError {
public:
    using InputError::InputError;
};

// Starts from options.epsilon (or the oracle's default). Each probe is a stage of `progress`,
// and its result a note. Throws BudgetNotReached with a one-line explanation when the budget
// cannot be reached: below the patch count, above what the area/depth limits and the rays
// allow, or not within the tolerance after max_probes. The options and the budget are checked
// where they are read (validate), not here. `ranks`
// share each probe's solve (solver.h). With `known`, the search reads it and adds the probes it
// solves to it.
BudgetResult solve_for_budget(const PatchMesh& mesh, const SolverOptions& options,
                              const BudgetOptions& budget, const SolveInputs& inputs = {},
                              Progress& progress = no_progress(),
                              const Ranks& ranks = Ranks::single(), KnownProbes* known = nullptr);

// Throws InputError on a tolerance outside (0, 1); a budget of 0 leaves means none. What reads
// a budget calls it (app/solve.cpp).
void validate(const BudgetOptions& budget);

}  // namespace hmcr
