// SPDX-License-Identifier: Apache-2.0
// The readers' tables of a study (studies/summary_table.h): table.md and table.tex from one
// model, the best mean of each error column marked in both, LaTeX's special characters escaped,
// a table wider than a page scaled to the line,
// and a meshing study's table.tex compiled by pdflatex where it is installed (Debian:
// texlive-latex-recommended, for booktabs), else checked line by line.
#include "studies/summary_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "common/output_set.h"
#include "studies/study.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

SummaryTable two_oracles() {
    SummaryTable t;
    t.row_title = "oracle";
    t.columns = {{"RMSEp", "{:.2f}", -1}, {"PSNRp (dB)", "{:.2f}", 1}, {"ε", "{:.3g}", 0}};
    t.rows = {{"power", "3/3", {mean_se({1.0, 1.2, 1.1}), mean_se({40, 41, 42}), mean_se({1e-6})}},
              {"kl", "2/3", {mean_se({2.0, 2.2}), mean_se({43, 44}), mean_se({7e-7})}}};
    return t;
}

TEST(SummaryTable, MarksTheBestMeanOfEachErrorColumnOnly) {
    const SummaryTable t = two_oracles();
    EXPECT_TRUE(is_best(t, 0, 0));  // lower RMSEp
    EXPECT_FALSE(is_best(t, 1, 0));
    EXPECT_TRUE(is_best(t, 1, 1));   // higher PSNR
    EXPECT_FALSE(is_best(t, 0, 2));  // not an error column
    EXPECT_FALSE(is_best(t, 1, 2));
    EXPECT_EQ(markdown(t),
              "| oracle | seeds | RMSEp | PSNRp (dB) | ε |\n"
              "|:--|--:|--:|--:|--:|\n"
              "| power | 3/3 | **1.10 ± 0.06** | 41.00 ± 0.58 | 1e-06 |\n"
              "| kl | 2/3 | 2.10 ± 0.10 | **43.50 ± 0.50** | 7e-07 |\n");
}

TEST(SummaryTable, LatexIsABooktabsTabularOfTheSameCells) {
    EXPECT_EQ(latex_tabular(two_oracles()),
              "\\begin{tabular}{@{}lrrrr@{}}\n\\toprule\n"
              "oracle & seeds & RMSEp & PSNRp (dB) & $\\varepsilon$ \\\\\n\\midrule\n"
              "power & 3/3 & \\textbf{1.10 $\\pm$ 0.06} & 41.00 $\\pm$ 0.58 & 1e-06 \\\\\n"
              "kl & 2/3 & 2.10 $\\pm$ 0.10 & \\textbf{43.50 $\\pm$ 0.50} & 7e-07 \\\\\n"
              "\\bottomrule\n\\end{tabular}\n");
}

TEST(SummaryTable, LatexTextEscapesWhatLatexWouldReadAsCode) {
    EXPECT_EQ(latex_text("a_b & 50% #1 $x {y} ~^\\"),
              "a\\_b \\& 50\\% \\#1 \\$x \\{y\\} \\textasciitilde{}\\textasciicircum{}"
              "\\textbackslash{}");
    EXPECT_EQ(latex_text("– ± ² ×"), "-- $\\pm$ $^2$ $\\times$");
    EXPECT_EQ(latex_text("line\nbreak"), "line break");  // would end a % comment
    EXPECT_EQ(latex_label("my scene_2.obj"), "my-scene-2-obj");
}

bool has_pdflatex() { return std::system("command -v pdflatex >/dev/null 2>&1") == 0; }

// `body` \input into an article with booktabs and graphicx, by pdflatex in `dir`: whether it
// compiled, and its log.
std::pair<bool, std::string> pdflatex(const TempDir& dir, const std::string& body) {
    dir.write("paper.tex",
              "\\documentclass{article}\n\\usepackage{booktabs}\n\\usepackage{graphicx}\n"
              "\\begin{document}\n" +
                  body + "\n\\end{document}\n");
    const std::string cmd = "cd '" + dir.path().string() +
                            "' && pdflatex -interaction=nonstopmode -halt-on-error paper.tex "
                            ">/dev/null 2>&1";
    const bool compiled = std::system(cmd.c_str()) == 0;
    return {compiled, read_file(dir.path() / "paper.log")};
}

// A sampling study's summary: 10 columns, 8 of them "mean ± se", wider than a page's text in
// \small; a table of a few columns is not.
TEST(SummaryTable, AFloatWiderThanTheLineIsScaledToIt) {
    SummaryTable wide;
    wide.row_title = "sampler";
    for (const char* title :
         {"RMSEa", "RMSEp", "PSNRa (dB)", "PSNRp (dB)", "spp", "max spp", "rays (M)", "seconds"}) {
        wide.columns.push_back({title, "{:.2f}", 0});
    }
    wide.rows = {{"uniform", "3/3", std::vector<MeanSe>(8, mean_se({32.37, 33.5, 31.2}))}};
    const std::string shrunk =
        "\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!}{%";
    const std::string floats = latex_float("Wide.", "tab:wide", wide) +
                               latex_float("Narrow.", "tab:narrow", two_oracles());
    EXPECT_NE(floats.find(shrunk), std::string::npos) << floats;
    if (!has_pdflatex()) GTEST_SKIP() << "no pdflatex: the floats checked by structure only";
    TempDir dir;
    const auto [compiled, log] = pdflatex(dir, floats);
    EXPECT_TRUE(compiled) << log;
    EXPECT_EQ(log.find("Overfull \\hbox"), std::string::npos) << log;
}

CellResult cell(const std::string& oracle, std::size_t budget, std::uint64_t seed, double error) {
    CellResult c;
    c.scene = "my_box";
    c.oracle = oracle;
    c.budget = budget;
    c.seed = seed;
    c.leaves = budget + seed;
    c.epsilon = 1e-6;
    c.views["camera"] = {1 + error, 2 + error, 40 - error, 30 - error};
    c.object_error.relative_l2 = error;
    c.object_error.samples = 100;
    return c;
}

TEST(StudyTables, TexHoldsOneTableFloatPerBudgetThatPdflatexCompiles) {
    TempDir dir;
    StudyOptions o;
    o.budgets = {100, 200};
    o.seeds = 2;
    o.output = dir.path();
    o.mesh_rays = 0;
    std::vector<CellResult> cells;
    for (std::size_t b : o.budgets)
        for (std::uint64_t s : {1, 2}) {
            cells.push_back(cell("power", b, s, 0.05 * double(s)));
            cells.push_back(cell("kl", b, s, 0.04 * double(s)));
        }
    OutputSet out(study_table_files(o), o.output);
    write_study_tables(out, "my_box", o, {"camera"}, cells);
    out.commit();
    const std::string tex = read_file(dir.path() / "table.tex");
    ASSERT_FALSE(tex.empty());
    // One float per budget, each a booktabs tabular; every row as many cells as the header.
    for (const char* part : {"\\begin{table}", "\\toprule", "\\midrule", "\\bottomrule",
                             "\\end{table}", "\\label{tab:my-box-100}", "\\label{tab:my-box-200}",
                             "Meshing study of my\\_box at 200 leaves"}) {
        EXPECT_NE(tex.find(part), std::string::npos) << part;
    }
    const std::regex row(R"(^(power|kl|oracle) &.*\\\\$)");
    int rows = 0;
    std::size_t columns = 0;
    std::istringstream lines(tex);
    for (std::string line; std::getline(lines, line);) {
        if (!std::regex_match(line, row)) continue;
        ++rows;
        const std::size_t amps = std::size_t(std::count(line.begin(), line.end(), '&'));
        if (columns == 0) columns = amps;
        EXPECT_EQ(amps, columns) << line;
    }
    EXPECT_EQ(rows, 6);       // header, power and kl, twice
    EXPECT_EQ(columns, 12u);  // seeds and 11 measures
    // kl's object error is the lower: bold, with its standard error.
    EXPECT_NE(tex.find("kl & 2/2 & "), std::string::npos);
    EXPECT_NE(tex.find("\\textbf{0.0600 $\\pm$ 0.0200}"), std::string::npos);
    if (!has_pdflatex()) GTEST_SKIP() << "no pdflatex: table.tex checked by structure only";
    const auto [compiled, log] = pdflatex(dir, "\\input{table.tex}");
    EXPECT_TRUE(compiled) << log;
    EXPECT_EQ(log.find("Overfull \\hbox"), std::string::npos) << log;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "paper.pdf"));
}

}  // namespace
}  // namespace hmcr::test
