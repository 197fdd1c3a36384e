// SPDX-License-Identifier: Apache-2.0
#include "app/run_summary.h"

#include "common/memory.h"
#include "common/rgb_json.h"
#include "radiosity/solver_settings.h"

namespace hmcr {
namespace {

nlohmann::json iterations_json(const SolveStats& st) {
    auto list = nlohmann::json::array();
    for (const auto& it : st.iterations) {
        list.push_back({{"rays", it.rays},
                        {"unshot_before_w", rgb_json(it.unshot_before)},
                        {"unshot_after_w", rgb_json(it.unshot_after)},
                        {"leaves_after", it.leaves_after},
                        {"seconds", it.seconds},
                        {"frozen", it.frozen},
                        {"control_constant", rgb_json(it.control_constant)}});
    }
    return list;
}

// Every setting, with the epsilon and thread count actually used.
nlohmann::json options_json(const SolverOptions& o, const SolveStats& st) {
    nlohmann::json j = settings_json(o);
    j["epsilon"] = st.epsilon;
    j["threads"] = st.threads;  // per rank
    j["ranks"] = st.ranks;
    return j;
}

nlohmann::json power_json(const SolveStats& st) {
    return {{"emitted_w", rgb_json(st.emitted_power)},
            {"escaped_w", rgb_json(st.escaped_power)},
            {"back_face_w", rgb_json(st.back_face_power)},
            {"unshot_remaining_w", rgb_json(st.unshot_power)},
            {"back_face_fraction", st.back_face_fraction()},
            {"back_face_warning", st.back_face_fraction() > 0.01}};
}

nlohmann::json cache_json(const SolveStats& st) {
    const double lookups = double(st.cache_hits + st.oracle_evaluations);
    return {{"capacity_pairs", st.cache_capacity},
            {"bytes", st.cache_bytes},
            {"hits", st.cache_hits},
            {"misses", st.cache_capacity ? st.oracle_evaluations : 0},
            {"hit_rate", st.cache_capacity && lookups > 0 ? double(st.cache_hits) / lookups : 0.0},
            {"evictions", st.cache_evictions}};
}

}  // namespace

nlohmann::json budget_json(const BudgetOptions& budget, const std::vector<BudgetProbe>& probes) {
    return {{"target_leaves", budget.leaves},
            {"tolerance", budget.tolerance},
            {"probes", nlohmann::json(probes)}};
}

nlohmann::json run_summary(const Scene& scene, const Solution& solution, const RunTimings& timings,
                           const std::string& command_line, const std::string& output) {
    const SolveStats& st = solution.stats;
    return {
        {"hmcr_version", HMCR_VERSION},
        {"command", command_line},
        {"output", output},
        {"scene",
         {{"name", scene.name},
          {"source", scene.source.string()},
          {"mesh", scene.mesh_path.string()},
          {"patches", st.patches},
          {"two_sided_patches", st.two_sided_patches},
          {"strict", scene.strict},
          {"repairs", scene.repairs.to_json()},
          {"total_area_m2", st.total_area},
          {"max_emitted_power_w", st.max_emitted_power}}},
        {"options", options_json(solution.options, st)},
        {"counts",
         {{"rays", st.rays},
          {"refining_rays", st.refining_rays},
          {"importance_rays", st.importance_rays},
          {"iterations", st.iterations.size()},
          {"oracle_calls", st.oracle_calls},
          {"oracle_evaluations", st.oracle_evaluations},
          {"cache_hits", st.cache_hits},
          {"lines_cast", st.lines_cast},
          {"elements", st.elements},
          {"leaves", st.leaves},
          {"cluster_leaves", st.cluster_leaves},
          {"faces", st.faces}}},
        {"power", power_json(st)},
        {"timings_s",
         {{"load", timings.load_seconds},
          {"setup", st.setup_seconds},
          {"shooting", st.shooting_seconds},
          {"refining", st.refining_seconds},
          {"importance", st.importance_seconds},
          {"push_pull", st.push_pull_seconds},
          {"oracles_all_threads", st.oracle_seconds},
          {"solve", st.total_seconds},
          {"output", timings.output_seconds},
          {"total", timings.total_seconds}}},
        {"link_cache", cache_json(st)},
        {"memory",
         {{"peak_bytes", peak_memory_bytes()},
          {"hierarchy_bytes", st.hierarchy_bytes},
          {"link_cache_bytes", st.cache_bytes}}},
        {"iterations", iterations_json(st)},
    };
}

}  // namespace hmcr
