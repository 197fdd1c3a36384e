// SPDX-License-Identifier: Apache-2.0
// A study's table.tex as a paper takes it: \input into \documentclass[10pt]{article}, pdflatex
// compiles it with no overfull box, and no table's font comes out below 8 pt, for the columns
// table.tex holds by default and for a set chosen with --columns; every column at once shrinks
// below 8 pt, which the same check catches. The font of a table is measured, not assumed: the
// test's preamble wraps \resizebox so that the log names, for every table, its natural width,
// the line's and the font size it is set in (\small: 9 pt), and the size once scaled follows.
// pdflatex is texlive-latex-recommended's (booktabs), which `make deps` installs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <regex>
#include <sstream>

#include "common/output_set.h"
#include "studies/sampling_study.h"
#include "studies/study.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

struct Compiled {
    bool ok = false;
    std::string log;
    std::vector<double> fonts;  // pt: every table's font as scaled to the line
};

// The preamble's \resizebox, before drawing, writes "hmcr-table: NATURAL LINE SIZE" to the log.
constexpr const char* kPaper =
    "\\documentclass[10pt]{article}\n\\usepackage{booktabs}\n\\usepackage{graphicx}\n"
    "\\makeatletter\n\\let\\hmcrresizebox\\resizebox\n"
    "\\renewcommand{\\resizebox}[3]{\\sbox\\z@{#3}%\n"
    "  \\typeout{hmcr-table: \\the\\wd\\z@\\space\\the\\linewidth\\space\\f@size}%\n"
    "  \\hmcrresizebox{#1}{#2}{#3}}\n\\makeatother\n"
    "\\begin{document}\n\\input{table.tex}\n\\end{document}\n";

// pdflatex on `dir`/table.tex inside kPaper.
Compiled compile(const std::filesystem::path& dir) {
    Compiled out;
    if (std::system("command -v pdflatex >/dev/null 2>&1") != 0) {
        ADD_FAILURE() << "no pdflatex: make deps installs texlive-latex-recommended";
        return out;
    }
    std::ofstream(dir / "paper.tex") << kPaper;
    const std::string cmd = "cd '" + dir.string() +
                            "' && pdflatex -interaction=nonstopmode -halt-on-error paper.tex "
                            ">/dev/null 2>&1";
    out.ok = std::system(cmd.c_str()) == 0;
    out.log = read_file(dir / "paper.log");
    const std::regex line(R"(hmcr-table: ([0-9.]+)pt ([0-9.]+)pt ([0-9.]+))");
    for (auto it = std::sregex_iterator(out.log.begin(), out.log.end(), line);
         it != std::sregex_iterator(); ++it) {
        const double natural = std::stod((*it)[1]), width = std::stod((*it)[2]);
        out.fonts.push_back(std::stod((*it)[3]) * std::min(1.0, width / natural));
    }
    return out;
}

std::size_t count_of(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// Compiles with no overfull box, and every float measured at 8 pt or more.
void expect_fits(const std::filesystem::path& dir) {
    const Compiled c = compile(dir);
    ASSERT_TRUE(c.ok) << c.log;
    EXPECT_EQ(c.log.find("Overfull \\hbox"), std::string::npos) << c.log;
    EXPECT_EQ(c.fonts.size(), count_of(read_file(dir / "table.tex"), "\\begin{table}"));
    EXPECT_FALSE(c.fonts.empty());
    for (double pt : c.fonts) EXPECT_GE(pt, 8.0) << c.log;
}

// The header line of each float's tabular: "oracle & seeds & ... \\".
std::vector<std::string> tex_headers(const std::string& tex) {
    std::vector<std::string> out;
    std::istringstream lines(tex);
    for (std::string line, previous; std::getline(lines, line); previous = line)
        if (previous == "\\toprule") out.push_back(line);
    return out;
}

// A cell of every oracle with errors of the sizes studies see: two views, a frozen re-solve.
CellResult tex_meshing_cell(const std::string& oracle, std::size_t budget, std::uint64_t seed,
                            double error) {
    CellResult c;
    c.scene = "cornell";
    c.oracle = oracle;
    c.budget = budget;
    c.seed = seed;
    c.leaves = budget + 37 * seed;
    c.epsilon = 6.75e-5 * (1 + 0.01 * double(seed));
    c.seconds = 123.4 + double(seed);
    c.finer_share = 0.021 * double(seed);
    for (const char* view : {"camera", "corner"}) {
        c.views[view] = {3.71 + error, 2.62 + error, 38.2 - error, 39.96 - error};
        c.mesh_views[view] = {1.71 + error, 1.62 + error, 43.2 - error, 44.29 - error};
    }
    c.object_error.relative_l2 = 0.0478 + 0.01 * error;
    c.mesh_object_error.relative_l2 = 0.0248 + 0.01 * error;
    c.rays = c.mesh_rays = 2'684'000;
    return c;
}

std::vector<CellResult> meshing_cells(const StudyOptions& o) {
    std::vector<CellResult> cells;
    const char* oracles[] = {"power", "ks", "mi", "kl", "cs", "hl", "vt"};
    for (std::size_t b : o.budgets)
        for (std::size_t k = 0; k < std::size(oracles); ++k)
            for (std::uint64_t s = 1; s <= std::uint64_t(o.seeds); ++s)
                cells.push_back(
                    tex_meshing_cell(oracles[k], b, s, 0.7 * double(k) + 0.13 * double(s)));
    return cells;
}

void write_meshing(const StudyOptions& o) {
    OutputSet out(study_table_files(o), o.output);
    write_study_tables(out, "cornell", o, {"camera", "corner"}, meshing_cells(o));
    out.commit();
}

StudyOptions meshing_options(const TempDir& dir) {
    StudyOptions o;
    o.budgets = {5000, 19000};
    o.output = dir.path();
    return o;
}

TEST(StudyTex, AMeshingStudysDefaultColumnsFitA10PtArticle) {
    const TempDir dir;
    write_meshing(meshing_options(dir));
    const std::string tex = read_file(dir.path() / "table.tex");
    EXPECT_EQ(tex_headers(tex),
              std::vector<std::string>(
                  2, "oracle & seeds & PSNRp (dB) & object error & mesh object error \\\\"));
    EXPECT_NE(tex.find("% Columns: seeds, psnr_p, object_error, mesh_object_error (hmcr study "
                       "--columns chooses from seeds, rmse_a,"),
              std::string::npos)
        << tex;
    // table.md keeps every column by default.
    EXPECT_NE(
        read_file(dir.path() / "table.md")
            .find("| oracle | seeds | RMSEa | RMSEp | PSNRa (dB) | PSNRp (dB) | object error "
                  "| mesh PSNRp (dB) | mesh object error | finer (%) | leaves | ε | seconds |"),
        std::string::npos);
    expect_fits(dir.path());
}

// --columns: both tables carry the columns named, in their order. This set is a little wider
// than the line (about 361 pt): scaled to it, its 9 pt stay above 8.
TEST(StudyTex, ChosenColumnsGoIntoBothTablesAndFit) {
    const TempDir dir;
    StudyOptions o = meshing_options(dir);
    o.columns = {"seeds", "rmse_p", "psnr_p", "object_error", "epsilon"};
    write_meshing(o);
    const std::string tex = read_file(dir.path() / "table.tex");
    EXPECT_EQ(tex_headers(tex)[0],
              "oracle & seeds & RMSEp & PSNRp (dB) & object error & $\\varepsilon$ \\\\");
    const std::string md = read_file(dir.path() / "table.md");
    EXPECT_EQ(count_of(md, "| oracle | seeds | RMSEp | PSNRp (dB) | object error | ε |\n"), 2u)
        << md;
    // ε as math, its standard error at the mean's last digit.
    EXPECT_NE(tex.find("$(6.89 \\pm 0.04) \\times 10^{-5}$"), std::string::npos) << tex;
    expect_fits(dir.path());
}

// Every column at once is wider than the line: the \resizebox shrinks its 9 pt below 8, and
// the measurement says so (this is what the checks above would catch).
TEST(StudyTex, EveryColumnAtOnceShrinksBelow8PtAndTheCheckSeesIt) {
    const TempDir dir;
    StudyOptions o = meshing_options(dir);
    o.columns = {"all"};
    write_meshing(o);
    EXPECT_EQ(count_of(tex_headers(read_file(dir.path() / "table.tex"))[0], "&"), 12u);
    const Compiled c = compile(dir.path());
    ASSERT_TRUE(c.ok) << c.log;
    ASSERT_EQ(c.fonts.size(), 2u);
    EXPECT_LT(c.fonts[0], 8.0);
}

// A sampling study of every sampler, two views, with its bias and noise table.
TEST(StudyTex, ASamplingStudysDefaultColumnsFitA10PtArticle) {
    const TempDir dir;
    SamplingStudyOptions o;
    o.output = dir.path();
    o.seeds = 3;
    std::vector<SamplingCell> cells;
    std::vector<std::string> samplers;
    ErrorSplits splits;
    for (const Criterion* s : o.samplers) samplers.emplace_back(s->name());
    for (std::size_t k = 0; k < samplers.size(); ++k)
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            SamplingCell c;
            c.scene = "mirrors";
            c.sampler = samplers[k];
            c.spp = 60;
            c.seed = seed;
            const double e = 0.3 * double(k) + 0.02 * double(seed);
            const double no_threshold = std::numeric_limits<double>::quiet_NaN();
            for (const char* view : {"general", "closeup"}) {
                c.views[view] = {{9.2 + e, 8.47 + e, 28.9 - e, 29.6 - e},
                                 60.02,
                                 1,
                                 1024,
                                 no_threshold,
                                 17'700'000,
                                 12.5 + e};
                splits[samplers[k]][view] = {1.17 + e, 9.16 + e};
            }
            cells.push_back(c);
        }
    OutputSet out(sampling_study_output_files(Scene{}, o), o.output);
    write_sampling_tables(out, "mirrors", o, {"general", "closeup"}, cells, {{60.0, splits}});
    out.commit();
    const std::vector<std::string> headers = tex_headers(read_file(dir.path() / "table.tex"));
    ASSERT_EQ(headers.size(), 4u);  // the mean over the views, the split, each view
    EXPECT_EQ(headers[0], "sampler & seeds & RMSEp & PSNRp (dB) & spp & rays (M) \\\\");
    EXPECT_EQ(headers[1], "sampler & bias RMSEp & noise RMSEp \\\\");
    expect_fits(dir.path());
}

}  // namespace
}  // namespace hmcr::test
