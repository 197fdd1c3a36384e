// SPDX-License-Identifier: Apache-2.0
#include "studies/summary_table.h"

#include <fmt/format.h>

#include <utility>

namespace hmcr {
namespace {

std::string cell_text(const SummaryTable& t, std::size_t r, std::size_t c) {
    return format_mean_se(t.rows[r].values[c], t.columns[c].format);
}

}  // namespace

bool is_best(const SummaryTable& t, std::size_t r, std::size_t c) {
    const int better = t.columns[c].better;
    const MeanSe& m = t.rows[r].values[c];
    if (better == 0 || m.n == 0) return false;
    for (const SummaryRow& other : t.rows) {
        const MeanSe& o = other.values[c];
        if (o.n > 0 && better * (o.mean - m.mean) > 0) return false;
    }
    return true;
}

std::string markdown(const SummaryTable& t) {
    std::string out = fmt::format("| {} |", t.row_title);
    std::string rule = "|:--|";
    if (t.seeds_column) {
        out += " seeds |";
        rule += "--:|";
    }
    for (const SummaryColumn& col : t.columns) {
        out += fmt::format(" {} |", col.title);
        rule += "--:|";
    }
    out += "\n" + rule + "\n";
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        out += fmt::format("| {} |", t.rows[r].name);
        if (t.seeds_column) out += fmt::format(" {} |", t.rows[r].seeds);
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            const std::string text = cell_text(t, r, c);
            out += is_best(t, r, c) ? fmt::format(" **{}** |", text) : fmt::format(" {} |", text);
        }
        out += "\n";
    }
    return out;
}

std::string latex_tabular(const SummaryTable& t) {
    std::string spec = "@{}l", header = latex_text(t.row_title);
    if (t.seeds_column) {
        spec += "r";
        header += " & seeds";
    }
    for (const SummaryColumn& col : t.columns) {
        spec += "r";
        header += " & " + latex_text(col.title);
    }
    std::string out =
        fmt::format("\\begin{{tabular}}{{{}@{{}}}}\n\\toprule\n{} \\\\\n\\midrule\n", spec, header);
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        out += latex_text(t.rows[r].name);
        if (t.seeds_column) out += " & " + latex_text(t.rows[r].seeds);
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            const std::string text = latex_text(cell_text(t, r, c));
            out += is_best(t, r, c) ? " & \\textbf{" + text + "}" : " & " + text;
        }
        out += " \\\\\n";
    }
    return out + "\\bottomrule\n\\end{tabular}\n";
}

std::string latex_float(const std::string& caption, const std::string& label,
                        const SummaryTable& table) {
    // Shrunk to the line where it is wider (\width is the tabular's natural width), as it is
    // otherwise: which tables fit depends on the paper's class and columns, not on hmcr.
    const std::string tabular =
        "\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}"
        "{!}{%\n" +
        latex_tabular(table) + "}\n";
    return fmt::format(
        "\n\\begin{{table}}[htbp]\n\\centering\n\\small\n\\caption{{{}}}\n\\label{{{}}}\n{}"
        "\\end{{table}}\n",
        caption, label, tabular);
}

std::string latex_text(std::string_view text) {
    static const std::pair<std::string_view, std::string_view> kReplacements[] = {
        {"\\", "\\textbackslash{}"},
        {"&", "\\&"},
        {"%", "\\%"},
        {"$", "\\$"},
        {"#", "\\#"},
        {"_", "\\_"},
        {"{", "\\{"},
        {"}", "\\}"},
        {"~", "\\textasciitilde{}"},
        {"^", "\\textasciicircum{}"},
        {"±", "$\\pm$"},
        {"–", "--"},
        {"ε", "$\\varepsilon$"},
        {"²", "$^2$"},
        {"×", "$\\times$"}};
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        bool replaced = false;
        for (const auto& [from, to] : kReplacements) {
            if (text.substr(i, from.size()) == from) {
                out += to;
                i += from.size();
                replaced = true;
                break;
            }
        }
        if (replaced) continue;
        // A line break would end a comment line and start LaTeX code.
        const bool control = static_cast<unsigned char>(text[i]) < 0x20;
        out += control ? ' ' : text[i];
        ++i;
    }
    return out;
}

std::string latex_label(std::string_view name) {
    std::string out(name);
    for (char& c : out) {
        const bool keep =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (!keep) c = '-';
    }
    return out;
}

}  // namespace hmcr
