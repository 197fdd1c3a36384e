// SPDX-License-Identifier: Apache-2.0
// The tables of a study for a reader (docs/design.md §6): one row per oracle or sampler, each
// column a mean ± standard error over the seeds, the best mean of each error column marked;
// written as Markdown (table.md) and as LaTeX with booktabs (table.tex), from one model so that
// the two always say the same.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "studies/mean_se.h"

namespace hmcr {

struct SummaryColumn {
    std::string title;   // as table.md writes it; latex_text() makes the LaTeX one
    std::string format;  // fmt format of one number, "{:.2f}"
    int better = 0;      // -1: lower is better, +1: higher, 0: not an error column
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

// Whether row r holds the best mean of column c: an error column, and no other row's mean better.
bool is_best(const SummaryTable& table, std::size_t r, std::size_t c);

// "| oracle | seeds | ... |", its rule and one line per row; the best in **bold**.
std::string markdown(const SummaryTable& table);

// A booktabs tabular of the same cells; the best in bold. Needs \usepackage{booktabs}.
std::string latex_tabular(const SummaryTable& table);

// A table float holding latex_tabular(table): "\n\begin{table}...\end{table}\n", the tabular
// in a \resizebox (graphicx) that scales it to \linewidth where it is wider, and leaves it as it
// is otherwise. The caption is LaTeX already.
std::string latex_float(const std::string& caption, const std::string& label,
                        const SummaryTable& table);

// Text for LaTeX: its special characters escaped, and the few non-ASCII characters hmcr's
// tables write (± – ε ² ×) as LaTeX, control characters as spaces; other bytes pass unchanged
// (UTF-8, LaTeX's default input).
std::string latex_text(std::string_view text);

// A \label key from a name: letters, digits and '-' kept, anything else made '-'.
std::string latex_label(std::string_view name);

}  // namespace hmcr
