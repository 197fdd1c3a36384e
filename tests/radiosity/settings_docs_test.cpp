// SPDX-License-Identifier: Apache-2.0
// The settings tables of docs/design.md and docs/usage.md against the one table of
// radiosity/solver_options.h: every setting has its row in both, marked as the table scopes it,
// with the table's default and the values the table allows.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "radiosity/element.h"
#include "radiosity/solver_settings.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace settings_docs {

// A table row's cells, between its outer bars.
std::vector<std::string> row_cells(const std::string& row) {
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t k = 1; k < row.size(); ++k) {
        if (row[k] == '|' && row[k - 1] != '\\') {
            const std::size_t first = cell.find_first_not_of(' ');
            cells.push_back(first == std::string::npos ? "" : cell.substr(first));
            cells.back().erase(cells.back().find_last_not_of(' ') + 1);
            cell.clear();
        } else {
            cell += row[k];
        }
    }
    return cells;
}

// The rows of the first table after the line `after` in a Markdown file, by the first cell's
// code (`oracle`, `--oracle`).
std::map<std::string, std::vector<std::string>> table_rows(const std::string& doc,
                                                           const std::string& after) {
    std::map<std::string, std::vector<std::string>> rows;
    const std::size_t start = doc.find(after);
    EXPECT_NE(start, std::string::npos) << "no line '" << after << "'";
    if (start == std::string::npos) return rows;
    std::size_t at = doc.find("\n|", start);
    while (at != std::string::npos && at + 1 < doc.size() && doc[at + 1] == '|') {
        const std::size_t end = doc.find('\n', at + 1);
        const std::string line = doc.substr(at + 1, end - at - 1);
        const std::vector<std::string> cells = row_cells(line);
        std::smatch m;
        if (!cells.empty() && std::regex_search(cells[0], m, std::regex("^`([^`]+)`"))) {
            rows[m[1]] = cells;
        }
        at = end;
    }
    return rows;
}

// The numbers a text states, as the docs and the table's words write them: 2,684,000, 10^-6,
// 1e-6, 1..4096; section numbers (§4.1) and link targets left out.
std::vector<double> numbers(std::string text) {
    text = std::regex_replace(text, std::regex(R"(\.\.)"), " .. ");
    text = std::regex_replace(text, std::regex(R"(\]\([^)]*\))"), "]");
    text = std::regex_replace(text, std::regex("§[0-9.]+"), "");
    text = std::regex_replace(text, std::regex(R"((\d),(\d))"), "$1$2");
    text = std::regex_replace(text, std::regex(R"(10\^(-?\d+))"), "1e$1");
    std::vector<double> out;
    const std::regex number(R"((^|[^\w.])(\d+(\.\d+)?(e-?\d+)?)(?![\w]))");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it) {
        out.push_back(std::stod((*it)[2]));
    }
    return out;
}

bool holds(const std::vector<double>& values, double v) {
    for (const double x : values) {
        if (std::abs(x - v) <= 1e-12 * std::abs(v)) return true;
    }
    return false;
}

// The cells after the default: where a row says which values are allowed.
std::string after_default(const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t k = 2; k < cells.size(); ++k) out += cells[k] + " | ";
    return out;
}

// Defaults that are no one value, and how each doc says them: ε is the oracle's own, the
// element limit a quarter of the machine's memory in elements of sizeof(Element) bytes.
struct Computed {
    std::string_view setting;
    std::string design;
    std::string usage;
};
std::vector<Computed> computed_defaults() {
    return {{"epsilon", "the oracle's", "the oracle's"},
            {"max_elements", fmt::format("memory / 4 / {} B", sizeof(Element)), "¼ of memory"}};
}

struct Docs {
    std::map<std::string, std::vector<std::string>> design, usage;
    std::string design_text;
};
Docs read_docs() {
    const std::filesystem::path dir = HMCR_DOCS_DIR;
    Docs d;
    d.design_text = read_file(dir / "design.md");
    d.design = table_rows(d.design_text, "| setting | default | meaning |");
    d.usage = table_rows(read_file(dir / "usage.md"), "| setting | default | valid | scene file |");
    return d;
}

}  // namespace settings_docs

using namespace settings_docs;

// A row in each doc for every setting, where a user sets it; design.md marks the command line's
// alone (run), usage.md's scene-file column says whether a scene file may set it.
TEST(SettingsDocs, EverySettingHasItsRowInDesignAndUsage) {
    const Docs docs = read_docs();
    ASSERT_FALSE(docs.design.empty());
    ASSERT_FALSE(docs.usage.empty());
    std::size_t rows = 0;
    for_each_setting([&](const auto& s) {
        const std::string name(s.name);
        if (s.scope == SettingScope::internal) {
            EXPECT_EQ(docs.design.count(name), 0u) << name;
            EXPECT_NE(docs.design_text.find("`" + name + "`, is set by"), std::string::npos)
                << "design.md does not name the internal setting " << name;
            EXPECT_EQ(docs.usage.count(s.flag()), 0u) << name;
            return;
        }
        ++rows;
        const auto design = docs.design.find(name);
        const auto usage = docs.usage.find(s.flag());
        if (design == docs.design.end() || usage == docs.usage.end()) {
            ADD_FAILURE() << (design == docs.design.end() ? "design.md" : "usage.md")
                          << "'s settings table has no row for " << name;
            return;
        }
        const bool run = s.scope == SettingScope::command_line;
        EXPECT_EQ(design->second[0].find("(run)") != std::string::npos, run)
            << "design.md: " << name << " is (run) exactly when the command line alone sets it";
        ASSERT_GE(usage->second.size(), 4u) << s.flag();
        EXPECT_EQ(usage->second[3], run ? "no" : "yes")
            << "usage.md's scene file column, " << s.flag();
    });
    EXPECT_EQ(docs.design.size(), rows) << "design.md's table: a row for each setting, no other";
    EXPECT_EQ(docs.usage.size(), rows) << "usage.md's table: a row for each setting, no other";
}

TEST(SettingsDocs, BothTablesGiveEveryDefault) {
    const Docs docs = read_docs();
    const std::vector<Computed> computed = computed_defaults();
    EXPECT_TRUE(std::isnan(SolverOptions{}.epsilon));
    EXPECT_EQ(SolverOptions{}.max_elements, default_max_elements());
    for_each_setting([&](const auto& s) {
        using T = std::remove_cvref_t<decltype(s.default_value)>;
        if (s.scope == SettingScope::internal) return;
        const auto design = docs.design.find(std::string(s.name));
        const auto usage = docs.usage.find(s.flag());
        if (design == docs.design.end() || usage == docs.usage.end()) return;  // test above
        const std::string& in_design = design->second.at(1);
        const std::string& in_usage = usage->second.at(1);
        const auto c = std::find_if(computed.begin(), computed.end(),
                                    [&](const Computed& x) { return x.setting == s.name; });
        if (c != computed.end()) {
            EXPECT_NE(in_design.find(c->design), std::string::npos) << s.name << ": " << in_design;
            EXPECT_NE(in_usage.find(c->usage), std::string::npos) << s.name << ": " << in_usage;
        } else if constexpr (NamedSetting<T>) {
            const std::string code = fmt::format("`{}`", SettingNames<T>::name(s.default_value));
            EXPECT_EQ(in_design, code) << s.name;
            EXPECT_EQ(in_usage, code) << s.flag();
        } else {
            const double v = double(s.default_value);
            const std::vector<double> d = numbers(in_design), u = numbers(in_usage);
            EXPECT_TRUE(!d.empty() && holds({d[0]}, v)) << s.name << ": " << in_design;
            EXPECT_TRUE(!u.empty() && holds({u[0]}, v)) << s.flag() << ": " << in_usage;
        }
    });
}

// The values the table allows, in both rows: every name of a named setting (the oracles by the
// command that lists them), every bound of a range, a half-open or open interval as written.
TEST(SettingsDocs, BothTablesGiveTheValuesTheTableAllows) {
    const Docs docs = read_docs();
    for_each_setting([&](const auto& s) {
        using T = std::remove_cvref_t<decltype(s.default_value)>;
        if (s.scope == SettingScope::internal) return;
        const auto design = docs.design.find(std::string(s.name));
        const auto usage = docs.usage.find(s.flag());
        if (design == docs.design.end() || usage == docs.usage.end()) return;
        for (const std::string& row :
             {after_default(design->second), after_default(usage->second)}) {
            const std::string where = fmt::format("{} ({}): {}", s.name, s.range, row);
            if constexpr (std::is_same_v<T, OracleRef>) {
                EXPECT_NE(row.find("`hmcr oracles`"), std::string::npos) << where;
            } else if constexpr (NamedSetting<T>) {
                for (const std::string_view value : EnumNames<T>::names) {
                    EXPECT_NE(row.find(fmt::format("`{}`", value)), std::string::npos) << where;
                }
            } else {
                const std::vector<double> bounds = numbers(s.range), stated = numbers(row);
                for (const double b : bounds) EXPECT_TRUE(holds(stated, b)) << b << ": " << where;
                std::smatch m;  // an open end matters: (0, 1] as written
                if (std::regex_search(s.range, m, std::regex(R"([\[(][\d.e-]+, [\d.e-]+[\])])")) &&
                    (m.str().front() == '(' || m.str().back() == ')')) {
                    EXPECT_NE(row.find(m.str()), std::string::npos) << where;
                }
                if (bounds.empty()) {
                    const std::string words = s.range == "positive" ? "> 0" : s.range;
                    EXPECT_NE(row.find(words), std::string::npos) << where;
                }
            }
        }
    });
}

}  // namespace hmcr::test
