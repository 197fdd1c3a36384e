// SPDX-License-Identifier: Apache-2.0
#include "studies/summary_table.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <set>
#include <utility>

#include "common/error.h"

namespace hmcr {
namespace {

// The level of the bold's test: a mean is significantly worse than the best at p < 0.05.
constexpr double kBoldLevel = 0.05;

std::string fixed(double x, int decimals) { return fmt::format("{:.{}f}", x, decimals); }

// The power of ten of x's first digit once x is rounded to `significant` digits (fmt rounds
// first: 9.996 to 3 digits is 1.00e+01, exponent 1).
int leading_exponent(double x, int significant) {
    const std::string e = fmt::format("{:.{}e}", x, significant - 1);
    return std::stoi(e.substr(e.find('e') + 1));
}

bool prints_as_zero(const std::string& text) {
    return text.find_first_not_of("-0.") == std::string::npos;
}

std::string superscript(int exponent) {
    static const char* const kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out;
    for (char c : std::to_string(exponent)) out += c == '-' ? "⁻" : kDigits[c - '0'];
    return out;
}

bool has_se(const MeanSe& m) { return m.n >= 2 && std::isfinite(m.se); }

// Whether `m` is worse than `best` at level kBoldLevel by a one-sided Welch t-test; a mean
// without a standard error, or beside a best without one, cannot be shown not worse.
bool significantly_worse(const MeanSe& m, const MeanSe& best, int better) {
    if (!has_se(m) || !has_se(best)) return true;
    const double worse_by = better * (best.mean - m.mean);  // > 0: m is worse
    const double va = m.se * m.se, vb = best.se * best.se;
    if (va + vb == 0) return worse_by > 0;  // both exact
    const double t = worse_by / std::sqrt(va + vb);
    const double df =
        (va + vb) * (va + vb) / (va * va / double(m.n - 1) + vb * vb / double(best.n - 1));
    const boost::math::students_t student(df);
    return boost::math::cdf(boost::math::complement(student, t)) < kBoldLevel;
}

std::string cell_markdown(const SummaryTable& t, std::size_t r, std::size_t c) {
    const std::string text =
        markdown_number(printed_number(t.rows[r].values[c], t.columns[c].style));
    return is_bold(t, r, c) ? fmt::format("**{}**", text) : text;
}

std::string cell_latex(const SummaryTable& t, std::size_t r, std::size_t c) {
    return latex_number(printed_number(t.rows[r].values[c], t.columns[c].style), is_bold(t, r, c));
}

}  // namespace

PrintedNumber printed_number(const MeanSe& v, NumberStyle style) {
    if (v.n == 0 || std::isnan(v.mean)) return {"–", "", 0};
    if (std::isinf(v.mean)) return {v.mean > 0 ? "inf" : "-inf", "", 0};
    const bool se = has_se(v) && v.se > 0;
    int exponent = 0, decimals = style.digits;
    if (style.significant) {
        // A mean of 0 takes its decimals from its standard error.
        const double first = v.mean != 0 ? v.mean : se ? v.se : 0;
        const int lead = first != 0 ? leading_exponent(first, style.digits) : 0;
        if (lead < -4 || lead >= style.digits) exponent = lead;
        decimals = std::max(0, style.digits - 1 - (lead - exponent));
    }
    const double scale = std::pow(10.0, -exponent);
    PrintedNumber out{fixed(v.mean * scale, decimals), "", exponent};
    if (se) {
        out.se = fixed(v.se * scale, decimals);
        if (prints_as_zero(out.se)) {
            out.se = fixed(v.se * scale, std::max(0, -leading_exponent(v.se * scale, 1)));
        }
    }
    return out;
}

std::string markdown_number(const PrintedNumber& n) {
    const std::string power =
        n.exponent != 0 ? fmt::format(" × 10{}", superscript(n.exponent)) : "";
    if (n.se.empty()) return n.mean + power;
    if (power.empty()) return fmt::format("{} ± {}", n.mean, n.se);
    return fmt::format("({} ± {}){}", n.mean, n.se, power);
}

std::string latex_number(const PrintedNumber& n, bool bold) {
    if (n.mean == "–") return "--";
    const std::string mean = n.mean == "inf" ? "\\infty" : n.mean == "-inf" ? "-\\infty" : n.mean;
    const std::string power = n.exponent != 0 ? fmt::format(" \\times 10^{{{}}}", n.exponent) : "";
    std::string body = mean + power;
    if (!n.se.empty()) {
        body = power.empty() ? fmt::format("{} \\pm {}", mean, n.se)
                             : fmt::format("({} \\pm {}){}", mean, n.se, power);
    }
    return bold ? fmt::format("$\\mathbf{{{}}}$", body) : fmt::format("${}$", body);
}

bool is_bold(const SummaryTable& t, std::size_t r, std::size_t c) {
    const int better = t.columns[c].better;
    const MeanSe& m = t.rows[r].values[c];
    if (better == 0 || m.n == 0 || std::isnan(m.mean)) return false;
    const MeanSe* best = &m;
    for (const SummaryRow& other : t.rows) {
        const MeanSe& o = other.values[c];
        if (o.n > 0 && better * (o.mean - best->mean) > 0) best = &o;
    }
    return best->mean == m.mean || !significantly_worse(m, *best, better);
}

std::string legend(const SummaryTable& t) {
    bool one_seed = false, exact = false, error_column = false;
    for (const SummaryColumn& col : t.columns) error_column |= col.better != 0;
    for (const SummaryRow& row : t.rows)
        for (const MeanSe& m : row.values) {
            one_seed |= m.n == 1 && std::isfinite(m.mean);
            exact |= m.n >= 2 && m.se == 0;
        }
    std::vector<std::string> alone;
    if (one_seed) alone.emplace_back("of one seed (a standard error needs two or more)");
    if (exact) alone.emplace_back("of seeds that agree exactly");
    std::string out = "Mean ± standard error over the seeds";
    if (!alone.empty()) out += fmt::format("; a mean alone is {}", fmt::join(alone, " or "));
    out += ".";
    return error_column ? out + " " + kBoldRule : out;
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
            out += fmt::format(" {} |", cell_markdown(t, r, c));
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
        for (std::size_t c = 0; c < t.columns.size(); ++c)
            out += fmt::format(" & {}", cell_latex(t, r, c));
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

std::vector<std::string> chosen_columns(const std::vector<std::string>& names,
                                        const TableColumns& columns, std::string_view study) {
    std::vector<std::string> out;
    for (const std::string& name : names) {
        if (name == "all") {
            out.insert(out.end(), columns.all.begin(), columns.all.end());
        } else if (std::find(columns.all.begin(), columns.all.end(), name) != columns.all.end()) {
            out.push_back(name);
        } else {
            throw InputError(
                fmt::format("study: unknown column {} of a {} study's tables "
                            "(valid: {}, all)",
                            quote(name), study, fmt::join(columns.all, ", ")));
        }
    }
    std::set<std::string> seen;
    for (const std::string& key : out) {
        if (!seen.insert(key).second) {
            throw InputError(fmt::format("study: column {} is given twice", key));
        }
    }
    return out;
}

ColumnChoice column_choice(const std::vector<std::string>& names, const TableColumns& columns,
                           std::string_view study) {
    if (names.empty()) return {columns.all, columns.tex_default};
    const std::vector<std::string> keys = chosen_columns(names, columns, study);
    return {keys, keys};
}

std::string latex_columns_comment(const std::vector<std::string>& keys,
                                  const TableColumns& columns) {
    return fmt::format("% Columns: {} (hmcr study --columns chooses from {}, or all).\n",
                       fmt::join(keys, ", "), fmt::join(columns.all, ", "));
}

std::string counted(std::size_t n, std::string_view noun) {
    return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
}

SummaryTable with_columns(const SummaryTable& t, const std::vector<std::string>& keys) {
    SummaryTable out;
    out.row_title = t.row_title;
    out.seeds_column = t.seeds_column && std::find(keys.begin(), keys.end(), "seeds") != keys.end();
    std::vector<std::size_t> kept;
    for (const std::string& key : keys)
        for (std::size_t c = 0; c < t.columns.size(); ++c)
            if (t.columns[c].key == key) kept.push_back(c);
    for (std::size_t c : kept) out.columns.push_back(t.columns[c]);
    for (const SummaryRow& row : t.rows) {
        SummaryRow r{row.name, row.seeds, {}};
        for (std::size_t c : kept) r.values.push_back(row.values[c]);
        out.rows.push_back(std::move(r));
    }
    return out;
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
