// SPDX-License-Identifier: Apache-2.0
// The readers' tables of a study (studies/summary_table.h): table.md and table.tex from one
// model; numbers as LaTeX math, a power of ten shared by a mean and its standard error; the bold
// of the best mean and of every mean a one-sided Welch t-test cannot call worse, on cases whose
// t statistic and degrees of freedom are worked out by hand against the t table; the columns
// chosen by name; LaTeX's special characters escaped. tests/studies/table_tex_test.cpp compiles
// the studies' table.tex.
#include "studies/summary_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/error.h"

namespace hmcr::test {
namespace {

constexpr double kNoSe = std::numeric_limits<double>::quiet_NaN();
constexpr NumberStyle kTwo{2, false}, kOne{1, false}, kWhole{0, false}, kThreeSignificant{3, true};

std::string md(double mean, double se, std::size_t n, NumberStyle style) {
    return markdown_number(printed_number({mean, se, n}, style));
}

std::string tex(double mean, double se, std::size_t n, NumberStyle style, bool bold = false) {
    return latex_number(printed_number({mean, se, n}, style), bold);
}

TEST(SummaryTable, NumbersAreMathWithAPowerOfTenWhereTheMagnitudeNeedsOne) {
    EXPECT_EQ(tex(1.1, 0.0577, 3, kTwo), "$1.10 \\pm 0.06$");
    EXPECT_EQ(md(1.1, 0.0577, 3, kTwo), "1.10 ± 0.06");
    EXPECT_EQ(tex(1.1, 0.0577, 3, kTwo, true), "$\\mathbf{1.10 \\pm 0.06}$");
    // ε: three significant digits, the standard error at the mean's last one, one exponent.
    EXPECT_EQ(tex(6.75e-5, 6.8e-7, 3, kThreeSignificant), "$(6.75 \\pm 0.07) \\times 10^{-5}$");
    EXPECT_EQ(md(6.75e-5, 6.8e-7, 3, kThreeSignificant), "(6.75 ± 0.07) × 10⁻⁵");
    EXPECT_EQ(tex(6.75e-5, kNoSe, 1, kThreeSignificant), "$6.75 \\times 10^{-5}$");
    EXPECT_EQ(tex(12345, kNoSe, 1, kThreeSignificant), "$1.23 \\times 10^{4}$");
    // Plain decimals from 10^-4 to 10^3 (printf's %g), rounding first: 9.996e-5 is 1.00e-4.
    EXPECT_EQ(tex(0.0478, 0.00031, 3, kThreeSignificant), "$0.0478 \\pm 0.0003$");
    EXPECT_EQ(tex(0.108, 0.0049, 3, kThreeSignificant), "$0.108 \\pm 0.005$");
    EXPECT_EQ(tex(6.75e-4, kNoSe, 1, kThreeSignificant), "$0.000675$");
    EXPECT_EQ(tex(9.996e-5, kNoSe, 1, kThreeSignificant), "$0.000100$");
    EXPECT_EQ(tex(0, 2e-6, 3, kThreeSignificant), "$(0.00 \\pm 2.00) \\times 10^{-6}$");
}

TEST(SummaryTable, AZeroStandardErrorIsNotPrintedAndATinyOneKeepsADigit) {
    // Seeds that agree exactly: the mean alone, no "± 0.0".
    EXPECT_EQ(tex(0, 0, 3, kOne), "$0.0$");
    EXPECT_EQ(md(5000, 0, 3, kWhole), "5000");
    // One seed: no standard error at all.
    EXPECT_EQ(tex(3.71, kNoSe, 1, kTwo), "$3.71$");
    // A standard error below the mean's last decimal: one significant digit of its own.
    EXPECT_EQ(tex(39.96, 0.0041, 3, kTwo), "$39.96 \\pm 0.004$");
    EXPECT_EQ(tex(39.96, 0.00096, 3, kTwo), "$39.96 \\pm 0.001$");
    // No value, and the PSNR of identical images.
    EXPECT_EQ(tex(kNoSe, kNoSe, 0, kTwo), "--");
    EXPECT_EQ(md(kNoSe, kNoSe, 0, kTwo), "–");
    EXPECT_EQ(tex(INFINITY, kNoSe, 2, kTwo), "$\\infty$");
    EXPECT_EQ(md(INFINITY, kNoSe, 2, kTwo), "inf");
}

// One column, lower is better, a row per value.
SummaryTable column_of(const std::vector<MeanSe>& values, int better = -1) {
    SummaryTable t;
    t.row_title = "oracle";
    t.seeds_column = false;
    t.columns = {{"rmse_p", "RMSEp", kTwo, better}};
    for (std::size_t i = 0; i < values.size(); ++i) {
        t.rows.push_back({"row" + std::to_string(i), "", {values[i]}});
    }
    return t;
}

std::vector<bool> bold_rows(const SummaryTable& t) {
    std::vector<bool> out;
    for (std::size_t r = 0; r < t.rows.size(); ++r) out.push_back(is_bold(t, r, 0));
    return out;
}

TEST(SummaryTable, OverlappingStandardErrorsAreBothBold) {
    // 3.71 ± 0.26 and 3.72 ± 0.04: t = 0.01 / 0.263, far below any critical value.
    EXPECT_EQ(bold_rows(column_of({{3.72, 0.04, 3}, {3.71, 0.26, 3}})),
              (std::vector<bool>{true, true}));
}

// Equal standard errors 0.1 of 3 seeds each: Welch's degrees of freedom are (0.02)² / (2 ×
// 0.01² / 2) = 4, and the one-sided 5% critical value of t with 4 degrees of freedom is 2.1318.
// 1.30 against 1.00: t = 0.30 / √0.02 = 2.1213, not significant; 1.31: t = 2.1920, significant.
TEST(SummaryTable, BoldStopsAtTheCriticalValueOfTheTTest) {
    EXPECT_EQ(bold_rows(column_of({{1.0, 0.1, 3}, {1.30, 0.1, 3}, {1.31, 0.1, 3}})),
              (std::vector<bool>{true, true, false}));
    // The same where higher is better (a PSNR).
    EXPECT_EQ(bold_rows(column_of({{40.0, 0.1, 3}, {39.70, 0.1, 3}, {39.69, 0.1, 3}}, 1)),
              (std::vector<bool>{true, true, false}));
}

// A best of standard error 0 (its seeds agree) beside one of 0.1 with 3 seeds: Welch's degrees
// of freedom are the other's alone, 2, whose critical value is 2.9200 (pooled ones, 4, would
// give 2.1318). 1.290: t = 2.90, not significant; 1.295: t = 2.95, significant.
TEST(SummaryTable, BoldTakesWelchsDegreesOfFreedom) {
    EXPECT_EQ(bold_rows(column_of({{1.0, 0, 3}, {1.290, 0.1, 3}, {1.295, 0.1, 3}})),
              (std::vector<bool>{true, true, false}));
}

TEST(SummaryTable, WithoutStandardErrorsOnlyTheBestIsBold) {
    // One seed each: however close, only the best (and a tie with it).
    EXPECT_EQ(bold_rows(column_of({{1.01, kNoSe, 1}, {1.0, kNoSe, 1}, {1.0, kNoSe, 1}})),
              (std::vector<bool>{false, true, true}));
    // A best of one seed tests nothing; nor does a row of one seed beside a best of three.
    EXPECT_EQ(bold_rows(column_of({{1.0, kNoSe, 1}, {1.01, 0.5, 3}})),
              (std::vector<bool>{true, false}));
    EXPECT_EQ(bold_rows(column_of({{1.0, 0.5, 3}, {1.01, kNoSe, 1}})),
              (std::vector<bool>{true, false}));
    // Two exact rows of different means: the worse is worse. No value is never bold.
    EXPECT_EQ(bold_rows(column_of({{1.0, 0, 2}, {1.01, 0, 2}, {kNoSe, kNoSe, 0}})),
              (std::vector<bool>{true, false, false}));
    // Not an error column: nothing bold.
    EXPECT_EQ(bold_rows(column_of({{1.0, 0.1, 3}, {2.0, 0.1, 3}}, 0)),
              (std::vector<bool>{false, false}));
}

SummaryTable two_oracles() {
    SummaryTable t;
    t.row_title = "oracle";
    t.columns = {{"rmse_p", "RMSEp", kTwo, -1},
                 {"psnr_p", "PSNRp (dB)", kTwo, 1},
                 {"epsilon", "ε", kThreeSignificant, 0}};
    t.rows = {{"power", "3/3", {mean_se({1.0, 1.2, 1.1}), mean_se({40, 41, 42}), mean_se({1e-6})}},
              {"kl", "2/3", {mean_se({2.0, 2.2}), mean_se({43, 44}), mean_se({7e-7})}}};
    return t;
}

// RMSEp: 1.10 ± 0.06 against 2.10 ± 0.10, t = 8.6; PSNRp: 43.50 ± 0.50 against 41.00 ± 0.58,
// t = 3.27 with 2.9 degrees of freedom (p ≈ 0.025): one bold each.
TEST(SummaryTable, MarkdownAndLatexCarryTheSameCellsAndBold) {
    const SummaryTable t = two_oracles();
    EXPECT_EQ(markdown(t),
              "| oracle | seeds | RMSEp | PSNRp (dB) | ε |\n"
              "|:--|--:|--:|--:|--:|\n"
              "| power | 3/3 | **1.10 ± 0.06** | 41.00 ± 0.58 | 1.00 × 10⁻⁶ |\n"
              "| kl | 2/3 | 2.10 ± 0.10 | **43.50 ± 0.50** | 7.00 × 10⁻⁷ |\n");
    EXPECT_EQ(latex_tabular(t),
              "\\begin{tabular}{@{}lrrrr@{}}\n\\toprule\n"
              "oracle & seeds & RMSEp & PSNRp (dB) & $\\varepsilon$ \\\\\n\\midrule\n"
              "power & 3/3 & $\\mathbf{1.10 \\pm 0.06}$ & $41.00 \\pm 0.58$ & "
              "$1.00 \\times 10^{-6}$ \\\\\n"
              "kl & 2/3 & $2.10 \\pm 0.10$ & $\\mathbf{43.50 \\pm 0.50}$ & "
              "$7.00 \\times 10^{-7}$ \\\\\n"
              "\\bottomrule\n\\end{tabular}\n");
}

TEST(SummaryTable, TheLegendSaysWhyAMeanStandsAlone) {
    const std::string rule =
        " Bold: the best mean of each error column and every mean not significantly worse than "
        "it (a one-sided Welch t-test at the 5% level); a mean without a standard error is bold "
        "only where it is the best.";
    EXPECT_EQ(legend(two_oracles()),
              "Mean ± standard error over the seeds; a mean alone is of one seed (a standard "
              "error needs two or more)." +
                  rule);
    EXPECT_EQ(legend(column_of({{1.0, 0.1, 3}, {1.0, 0, 3}})),
              "Mean ± standard error over the seeds; a mean alone is of seeds that agree "
              "exactly." +
                  rule);
    EXPECT_EQ(legend(column_of({{1.0, 0.1, 3}}, 0)), "Mean ± standard error over the seeds.");
    EXPECT_EQ(counted(1, "view"), "1 view");
    EXPECT_EQ(counted(3, "seed"), "3 seeds");
}

TEST(SummaryTable, ColumnsAreChosenByNameInTheirOrder) {
    const TableColumns columns{{"seeds", "rmse_p", "psnr_p", "epsilon"}, {"seeds", "rmse_p"}};
    EXPECT_EQ(chosen_columns({"psnr_p", "seeds"}, columns, "meshing"),
              (std::vector<std::string>{"psnr_p", "seeds"}));
    EXPECT_EQ(chosen_columns({"all"}, columns, "meshing"), columns.all);
    const ColumnChoice none = column_choice({}, columns, "meshing");
    EXPECT_EQ(none.markdown, columns.all);
    EXPECT_EQ(none.latex, columns.tex_default);
    const ColumnChoice chosen = column_choice({"epsilon"}, columns, "meshing");
    EXPECT_EQ(chosen.markdown, chosen.latex);

    // The seeds column stays second; the others follow the order given.
    const SummaryTable t = with_columns(two_oracles(), {"epsilon", "seeds", "rmse_p"});
    EXPECT_EQ(markdown(t),
              "| oracle | seeds | ε | RMSEp |\n"
              "|:--|--:|--:|--:|\n"
              "| power | 3/3 | 1.00 × 10⁻⁶ | **1.10 ± 0.06** |\n"
              "| kl | 2/3 | 7.00 × 10⁻⁷ | 2.10 ± 0.10 |\n");
    EXPECT_EQ(markdown(with_columns(two_oracles(), {"psnr_p"})),
              "| oracle | PSNRp (dB) |\n"
              "|:--|--:|\n"
              "| power | 41.00 ± 0.58 |\n"
              "| kl | **43.50 ± 0.50** |\n");
}

TEST(SummaryTable, AnUnknownOrRepeatedColumnIsRefusedNamingTheValidOnes) {
    const TableColumns columns{{"seeds", "rmse_p", "psnr_p"}, {"seeds"}};
    try {
        chosen_columns({"rmse_p", "spp"}, columns, "meshing");
        ADD_FAILURE() << "spp accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "study: unknown column 'spp' of a meshing study's tables (valid: seeds, "
                     "rmse_p, psnr_p, all)");
    }
    EXPECT_THROW(chosen_columns({"rmse_p", "all"}, columns, "meshing"), InputError);
    EXPECT_THROW(column_choice({"seeds", "seeds"}, columns, "sampling"), InputError);
}

TEST(SummaryTable, LatexTextEscapesWhatLatexWouldReadAsCode) {
    EXPECT_EQ(latex_text("a_b & 50% #1 $x {y} ~^\\"),
              "a\\_b \\& 50\\% \\#1 \\$x \\{y\\} \\textasciitilde{}\\textasciicircum{}"
              "\\textbackslash{}");
    EXPECT_EQ(latex_text("– ± ² ×"), "-- $\\pm$ $^2$ $\\times$");
    EXPECT_EQ(latex_text("line\nbreak"), "line break");  // would end a % comment
    EXPECT_EQ(latex_label("my scene_2.obj"), "my-scene-2-obj");
}

}  // namespace
}  // namespace hmcr::test
