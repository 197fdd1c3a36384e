// SPDX-License-Identifier: Apache-2.0
// The tables of a study for a reader (docs/design.md §6): one row per oracle or sampler, each
// column a mean ± standard error over the seeds; in bold, the best mean of each error column and
// every mean not significantly worse than it (a one-sided Welch t-test at 5%). Written as
// Markdown (table.md) and as LaTeX with booktabs (table.tex), from one model so that the two
// always say the same; the columns they carry are chosen by name (`--columns`).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "studies/mean_se.h"

namespace hmcr {

// How a column prints its numbers: `digits` decimals, or with `significant`, `digits`
// significant digits, as plain decimals from 10^-4 up to 10^digits and beyond as a power of ten
// shared by the mean and its standard error (printf's %g rule).
struct NumberStyle {
    int digits = 2;
    bool significant = false;
};

struct SummaryColumn {
    std::string key;    // the name --columns gives it, as table.csv's header: "psnr_p"
    std::string title;  // as table.md writes it; latex_text() makes the LaTeX one
    NumberStyle style;
    int better = 0;  // -1: lower is better, +1: higher, 0: not an error column
};

struct SummaryRow {
    std::string name;            // the oracle or sampler
    std::string seeds;           // "3/3": the seeds that succeeded of those run; "" for none
    std::vector<MeanSe> values;  // one per column
};

struct SummaryTable {
    std::string row_title;  // "oracle", "sampler"
    bool seeds_column = true;
    std::vector<SummaryColumn> columns;
    std::vector<SummaryRow> rows;
};

// A mean and its standard error as a table prints them: decimal digits, and a power of ten
// they share (0: none). `se` is empty where there is none to print: one seed, or seeds that
// agree exactly (a standard error of 0). `mean` is "–" for no value, "inf" or "-inf".
struct PrintedNumber {
    std::string mean, se;
    int exponent = 0;
};

// The se is printed at the mean's last decimal, or where that would round it to 0, with one
// significant digit of its own ("39.96 ± 0.004").
PrintedNumber printed_number(const MeanSe& value, NumberStyle style);

// "41.00 ± 0.58", "1.10", "(6.75 ± 0.07) × 10⁻⁵", "–".
std::string markdown_number(const PrintedNumber& number);
// "$41.00 \pm 0.58$", "$(6.75 \pm 0.07) \times 10^{-5}$", "--"; in \mathbf where bold.
std::string latex_number(const PrintedNumber& number, bool bold);

// Whether row r's value of column c is bold: an error column, and either the best mean of the
// column (ties all bold) or not significantly worse than it: a one-sided Welch t-test of "worse
// than the best" with p ≥ 0.05 (Welch-Satterthwaite degrees of freedom). A value without a
// standard error (fewer than two seeds) is bold only where it is the best, as is every value
// where the best has none.
bool is_bold(const SummaryTable& table, std::size_t r, std::size_t c);

// What the numbers and the bold of `table` mean, for a caption: "Mean ± standard error over the
// seeds ...", saying why a mean stands alone where one does.
std::string legend(const SummaryTable& table);

// The bold rule as one sentence, for a document's description of all its tables.
inline constexpr const char* kBoldRule =
    "Bold: the best mean of each error column and every mean not significantly worse than it (a "
    "one-sided Welch t-test at the 5% level); a mean without a standard error is bold only where "
    "it is the best.";

// "| oracle | seeds | ... |", its rule and one line per row; the bold in **bold**.
std::string markdown(const SummaryTable& table);

// A booktabs tabular of the same cells, numbers in math mode, the same bold. Needs
// \usepackage{booktabs}.
std::string latex_tabular(const SummaryTable& table);

// A table float holding latex_tabular(table): "\n\begin{table}...\end{table}\n", in \small,
// the tabular in a \resizebox (graphicx) that scales it to \linewidth where it is wider, and
// leaves it as it is otherwise. The caption is LaTeX already.
std::string latex_float(const std::string& caption, const std::string& label,
                        const SummaryTable& table);

// The columns --columns may name in a kind of study's tables: "seeds", then every column's key,
// and those table.tex holds when --columns is not given.
struct TableColumns {
    std::vector<std::string> all;
    std::vector<std::string> tex_default;
};

// The keys `names` give, in their order, "all" standing for every one; throws InputError, one
// line naming the valid keys, on an unknown or repeated name. `study` ("meshing", "sampling")
// names the kind in the message.
std::vector<std::string> chosen_columns(const std::vector<std::string>& names,
                                        const TableColumns& columns, std::string_view study);

// The keys of table.md's and table.tex's columns: those `names` choose (chosen_columns), or
// where there are none, every column in table.md and the tex_default in table.tex.
struct ColumnChoice {
    std::vector<std::string> markdown, latex;
};
ColumnChoice column_choice(const std::vector<std::string>& names, const TableColumns& columns,
                           std::string_view study);

// table.tex's comment line naming its columns and those --columns may choose.
std::string latex_columns_comment(const std::vector<std::string>& keys,
                                  const TableColumns& columns);

// "1 view", "3 views".
std::string counted(std::size_t n, std::string_view noun);

// `table` with only the columns `keys` name, in their order; the seeds column (where the table
// has one) stays second where "seeds" is among them and goes where it is not. Keys the table
// lacks are skipped.
SummaryTable with_columns(const SummaryTable& table, const std::vector<std::string>& keys);

// Text for LaTeX: its special characters escaped, and the few non-ASCII characters hmcr's
// tables write (± – ε ² ×) as LaTeX, control characters as spaces; other bytes pass unchanged
// (UTF-8, LaTeX's default input).
std::string latex_text(std::string_view text);

// A \label key from a name: letters, digits and '-' kept, anything else made '-'.
std::string latex_label(std::string_view name);

}  // namespace hmcr
