// What the two kinds of study (studies/study.h: oracles at element budgets; studies/
// sampling_study.h: pixel samplers at one spp) share about their cells: a cell's notes within
// the study's progress, and the rule for a cell file left by an earlier run.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/error.h"
#include "common/progress.h"
#include "common/text_file.h"

namespace hmcr {

// A cell's searches as notes of the study ("[3/21] CELL: budget probe 2: ..."), without their
// fractions: a study is hundreds of solves or images.
class CellNotes final : public Progress {
public:
    CellNotes(Progress& study, std::string prefix) : m_study(study), m_prefix(std::move(prefix)) {}
    void stage(std::string_view) override {}
    void advance(double) override {}
    void note(std::string_view line) override { m_study.note(m_prefix + std::string(line)); }

private:
    Progress& m_study;
    std::string m_prefix;
};

// "rays is 200000 now": the settings that differ between a cell file and this run.
std::string settings_difference(const nlohmann::json& old_settings, const nlohmann::json& now);

// How an earlier run's cell file is taken.
template <class Cell>
struct CellFileRule {
    std::function<Cell(const nlohmann::json&)> parse;  // throws on a malformed cell
    std::function<bool(const Cell&)> is_this_cell;     // scene, criterion, size, seed match
    nlohmann::json settings;                           // this run's; Cell::settings must equal it
    bool redo_other_settings = false;
};

// The cell of `file` from an earlier run, if it is usable. An unreadable or foreign file is
// computed again (a truncated write, an edited file) and said so in `notes`; one made with other
// settings is refused (InputError naming the file) unless rule.redo_other_settings.
template <class Cell>
std::optional<Cell> read_previous_cell(const std::filesystem::path& file, const CellFileRule<Cell>& rule,
                                  Progress& notes) {
    if (!std::filesystem::exists(file)) return std::nullopt;
    Cell cell;
    try {
        cell = read_json_file(file, rule.parse);
    } catch (const InputError& e) {
        notes.note(std::string("unreadable (") + e.what() + "); computing it again");
        return std::nullopt;
    }
    if (!rule.is_this_cell(cell)) {
        notes.note("the file holds another cell; computing it again");
        return std::nullopt;
    }
    if (cell.settings == rule.settings) return cell;
    if (rule.redo_other_settings) {
        notes.note("made with other settings; computing it again");
        return std::nullopt;
    }
    throw InputError(file.string(),
                     fmt::format("made with other settings ({}); use another output folder, or "
                                 "--redo to compute such cells again",
                                 settings_difference(cell.settings, rule.settings)));
}

}  // namespace hmcr
