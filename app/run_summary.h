// SPDX-License-Identifier: Apache-2.0
// The JSON run summary written beside every solution (docs/design.md §5).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "meshes/scene.h"
#include "radiosity/budget_search.h"

namespace hmcr {

struct RunTimings {
    double load_seconds = 0;
    double output_seconds = 0;
    double total_seconds = 0;
};

nlohmann::json run_summary(const Scene& scene, const Solution& solution, const RunTimings& timings,
                           const std::string& command_line, const std::string& output);

// The summary's "budget": the target, the tolerance and every probe of the search.
nlohmann::json budget_json(const BudgetOptions& budget, const std::vector<BudgetProbe>& probes);

}  // namespace hmcr
