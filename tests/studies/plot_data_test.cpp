// SPDX-License-Identifier: Apache-2.0
// The numbers a study's plots show (studies/plot_data.h): the tables' means and standard errors
// over the same cells, the mesh panel only where the mesh error was measured, RMSEp against a
// traced reference, error against spp only where the cells hold several target spp, and a
// table.json of another kind, or of too many budgets, refused.
#include "studies/plot_data.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

using nlohmann::json;

CellResult meshing_cell(const std::string& oracle, std::size_t budget, std::size_t leaves,
                        double error) {
    CellResult c;
    c.scene = "box";
    c.oracle = oracle;
    c.budget = budget;
    c.leaves = leaves;
    c.views["camera"] = {1, 3 * error, 40, 30};
    c.object_error.relative_l2 = error;
    c.object_error.samples = 10;
    return c;
}

const json& panel(const json& data, std::size_t figure, std::size_t panel) {
    return data.at("figures").at(figure).at("panels").at(panel);
}

TEST(PlotData, MeshingPointsAreTheMeansAndStandardErrorsOfEachBudget) {
    std::vector<CellResult> cells = {
        meshing_cell("kl", 100, 98, 0.2), meshing_cell("kl", 100, 102, 0.4),
        meshing_cell("kl", 200, 200, 0.1), meshing_cell("power", 100, 100, 0.3)};
    cells.push_back(meshing_cell("power", 200, 0, 0));
    cells.back().status = "failed";  // left out, as the tables leave it out
    const json data = meshing_plot_data("box", cells);
    EXPECT_EQ(data.at("figures").at(0).at("name"), "error_vs_elements");
    ASSERT_EQ(data.at("figures").at(0).at("panels").size(), 1u);  // no mesh error measured
    const json& solution = panel(data, 0, 0);
    EXPECT_EQ(solution.at("y_label"), "object error (relative L2)");
    EXPECT_EQ(solution.at("x_ticks"), json({100, 200}));
    const json& kl = solution.at("series").at(0);
    EXPECT_EQ(kl.at("name"), "kl");
    ASSERT_EQ(kl.at("points").size(), 2u);
    const json& p = kl.at("points").at(0);
    EXPECT_DOUBLE_EQ(p.at("x").get<double>(), 100);
    EXPECT_DOUBLE_EQ(p.at("x_se").get<double>(), 2);  // sd 2.83 over sqrt(2)
    EXPECT_DOUBLE_EQ(p.at("y").get<double>(), 0.3);
    EXPECT_NEAR(p.at("y_se").get<double>(), 0.1, 1e-15);
    EXPECT_EQ(p.at("n"), 2);
    EXPECT_TRUE(kl.at("points").at(1).at("y_se").is_null());         // one seed: no standard error
    EXPECT_EQ(solution.at("series").at(1).at("points").size(), 1u);  // power's failed cell
}

TEST(PlotData, MeshPanelWhereMeasuredAndRmsepAgainstATracedReference) {
    CellResult c = meshing_cell("kl", 100, 100, 0.2);
    c.mesh_rays = 1000;
    c.mesh_object_error.relative_l2 = 0.1;
    c.mesh_object_error.samples = 10;
    EXPECT_EQ(panel(meshing_plot_data("box", {c}), 0, 1).at("title"), "mesh (frozen re-solve)");
    c.object_error.relative_l2 = std::numeric_limits<double>::quiet_NaN();  // traced reference
    const json traced = meshing_plot_data("box", {c});
    EXPECT_EQ(panel(traced, 0, 0).at("y_label"), "RMSEp (0–255)");
    EXPECT_DOUBLE_EQ(
        panel(traced, 0, 0).at("series").at(0).at("points").at(0).at("y").get<double>(), 0.6);
}

SamplingCell sampling_cell(const std::string& sampler, double spp, double rmse_p) {
    SamplingCell c;
    c.scene = "box";
    c.sampler = sampler;
    c.spp = spp;
    c.views["a"].errors = {0, rmse_p, 0, 0};
    c.views["a"].spp = spp;
    c.views["b"].errors = {0, 3 * rmse_p, 0, 0};
    c.views["b"].spp = spp + 2;
    return c;
}

TEST(PlotData, SamplingBarsWithTheSplitOfEachSppAndErrorAgainstSppAtSeveral) {
    const SppErrorSplits splits = {{16, {{"uniform", {{"a", {3, 4}}, {"b", {0, 0}}}}}}};
    const json one = sampling_plot_data(
        "box", {sampling_cell("uniform", 16, 1), sampling_cell("srhe", 16, 2)}, splits);
    ASSERT_EQ(one.at("figures").size(), 1u);
    const json& bars = panel(one, 0, 0);
    EXPECT_EQ(bars.at("categories"), json({"uniform", "srhe"}));
    ASSERT_EQ(bars.at("groups").size(), 3u);
    EXPECT_DOUBLE_EQ(bars.at("groups").at(0).at("values").at(1).at("y").get<double>(), 4);
    EXPECT_DOUBLE_EQ(bars.at("groups").at(1).at("values").at(0).at("y").get<double>(),
                     std::sqrt(4.5));  // RMS of the views' biases
    EXPECT_TRUE(bars.at("groups").at(1).at("values").at(1).at("y").is_null());  // no split
    const json several = sampling_plot_data(
        "box", {sampling_cell("uniform", 16, 2), sampling_cell("uniform", 64, 1)}, splits);
    ASSERT_EQ(several.at("figures").size(), 2u);
    // Every panel has the bias and noise bars, of its own spp's seeds: 16 has a split, 64 none.
    ASSERT_EQ(panel(several, 0, 0).at("groups").size(), 3u);
    EXPECT_DOUBLE_EQ(
        panel(several, 0, 0).at("groups").at(1).at("values").at(0).at("y").get<double>(),
        std::sqrt(4.5));
    ASSERT_EQ(panel(several, 0, 1).at("groups").size(), 3u);
    EXPECT_TRUE(panel(several, 0, 1).at("groups").at(2).at("values").at(0).at("y").is_null());
    const json& lines = panel(several, 1, 0);
    EXPECT_EQ(several.at("figures").at(1).at("name"), "error_vs_spp");
    EXPECT_DOUBLE_EQ(lines.at("series").at(0).at("points").at(1).at("x").get<double>(), 65);
}

// A table.json of several spp values holds its splits by spp first: each panel gets its own.
TEST(PlotData, ASamplingTableOfSeveralSppGivesEachPanelItsSplit) {
    TempDir dir;
    json cells = json::array();
    for (double spp : {16.0, 64.0})
        cells.push_back(sampling_cell_to_json(sampling_cell("srhe", spp, 1)));
    const json split = {{"bias_rmse_p", 3}, {"noise_rmse_p", 4}};
    const json table = {{"scene", "box"},
                        {"options", {{"samplers", {"srhe"}}, {"spp", {16, 64}}}},
                        {"error_split", {{"64", {{"srhe", {{"a", split}}}}}}},
                        {"cells", cells}};
    const json data = plot_data_of_table(dir.write("table.json", table.dump()));
    const json& at16 = panel(data, 0, 0).at("groups");
    const json& at64 = panel(data, 0, 1).at("groups");
    ASSERT_EQ(at64.size(), 3u);
    EXPECT_DOUBLE_EQ(at64.at(1).at("values").at(0).at("y").get<double>(), 3);  // bias
    EXPECT_DOUBLE_EQ(at64.at(2).at("values").at(0).at("y").get<double>(), 4);  // noise
    EXPECT_TRUE(at16.at(1).at("values").at(0).at("y").is_null());
}

TEST(PlotData, TableOfNoStudyUnknownOracleOrTooManyBudgetsIsRefused) {
    TempDir dir;
    const auto error_of = [&](const std::string& text) {
        try {
            plot_data_of_table(dir.write("table.json", text));
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error_of(R"({"scene": "box", "options": {}, "cells": []})")
                  .find("table.json: neither a meshing study's table"),
              std::string::npos);
    json cell = cell_to_json(meshing_cell("nope", 1, 1, 0.1));
    json table = {{"scene", "box"}, {"options", {{"budgets", {1}}}}, {"cells", {cell}}};
    EXPECT_NE(error_of(table.dump()).find("unknown oracle 'nope'"), std::string::npos);
    table["cells"] = json::array();
    for (std::size_t b = 1; b <= kMaxPlotPoints + 1; ++b) {
        table["cells"].push_back(cell_to_json(meshing_cell("kl", b, b, 0.1)));
    }
    EXPECT_NE(error_of(table.dump()).find("1001 budgets; a plot shows at most 1000"),
              std::string::npos);
    table["cells"].erase(table["cells"].begin());
    EXPECT_EQ(plot_data_of_table(dir.write("table.json", table.dump()))
                  .at("figures")
                  .at(0)
                  .at("panels")
                  .at(0)
                  .at("series")
                  .at(0)
                  .at("points")
                  .size(),
              kMaxPlotPoints);
}

}  // namespace
}  // namespace hmcr::test
