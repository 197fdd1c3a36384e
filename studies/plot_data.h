// SPDX-License-Identifier: Apache-2.0
// The numbers a study's plots show (docs/design.md §6), written to STUDY/plots/plot_data.json
// for scripts/plot_study.py to draw. The data is a list of figures, each a row of panels:
//   lines: series of points (x ± se, y ± se, n), log-log, with error bars both ways;
//   bars:  a value ± se per category (an oracle or sampler) and group (an error measure).
// Means and standard errors are the tables' (studies/mean_se.h) over the same cells, so a plot
// shows what table.md says.
//
// Meshing study: `error_vs_elements`, error against leaves per oracle, one point per budget: the
// solution's object error beside the mesh's (the frozen re-solve's); RMSEp instead against a
// traced reference, which has no object error.
// Sampling study: `error_by_sampler`, RMSEp per sampler at each target spp, with the bias and
// noise split of that spp's seeds as two more bars (empty where a sampler has fewer than two);
// and, where its cells hold two or more target spp, `error_vs_spp`: RMSEp against the spp
// reached, per sampler.
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "studies/sampling_study.h"
#include "studies/study.h"

namespace hmcr {

// A plot holds at most this many budgets or target spp (points of a series), so that a table
// of any size is drawn in bounded time.
inline constexpr std::size_t kMaxPlotPoints = 1000;

nlohmann::json meshing_plot_data(const std::string& scene, const std::vector<CellResult>& cells);
nlohmann::json sampling_plot_data(const std::string& scene, const std::vector<SamplingCell>& cells,
                                  const SppErrorSplits& splits);

// The plot data of the study whose table.json is `table`, of either kind. Throws InputError
// naming the file when it is no study's table, names an unknown oracle or sampler, or holds
// more than kMaxPlotPoints budgets or target spp.
nlohmann::json plot_data_of_table(const std::filesystem::path& table);

// STUDY/plots/plot_data.json, where a study writes its plot data (one of its output set).
std::filesystem::path plot_data_file(const std::filesystem::path& study);
// The text of that file.
std::string plot_data_text(const nlohmann::json& data);

}  // namespace hmcr
