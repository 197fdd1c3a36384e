// SPDX-License-Identifier: Apache-2.0
// What the two kinds of study (studies/study.h: oracles at element budgets; studies/
// sampling_study.h: pixel samplers at spp values) share about their cells: a cell's notes within
// the study's progress, the limits on their number and seeds, the rule for a cell file left by
// an earlier run, and the loop over the cells.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/output_paths.h"
#include "common/output_set.h"
#include "common/progress.h"
#include "common/stopwatch.h"
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

// The most cells a study may have (oracles x budgets x seeds, or samplers x seeds): each is
// at least one solve or image, and the study holds every cell's result for its tables
// (docs/usage.md#bad-input).
inline constexpr std::uint64_t kMaxStudyCells = 10000;

// Throws InputError when a study of `cells` cells = `per_seed` x `seeds` would pass
// kMaxStudyCells, or its seeds first_seed .. first_seed + seeds - 1 would pass 2^64 - 1.
void check_study_size(std::uint64_t per_seed, int seeds, std::uint64_t first_seed);

// "rays is 200000 now": the settings that differ between a cell file and this run.
std::string settings_difference(const nlohmann::json& old_settings, const nlohmann::json& now);

// "no result for view 'top'" for the first of `views` that `results` (a cell's, by view name)
// does not hold, or nothing.
template <class Result>
std::string missing_view(const std::map<std::string, Result>& results,
                         const std::vector<std::string>& views, const char* what = "result") {
    for (const std::string& v : views) {
        if (results.count(v) == 0) return fmt::format("no {} for view {}", what, quote(v));
    }
    return "";
}

// How an earlier run's cell file is taken.
template <class Cell>
struct CellFileRule {
    std::function<Cell(const nlohmann::json&)> parse;  // throws on a malformed cell
    std::function<bool(const Cell&)> is_this_cell;     // scene, criterion, size, seed match
    nlohmann::json settings;                           // this run's; Cell::settings must equal it
    bool redo_other_settings = false;
    // What the cell lacks that this study needs of it ("no result for view 'side'"), or
    // nothing: a cell file edited or made for a scene of other views is computed again.
    std::function<std::string(const Cell&)> lacks;
};

// The cell of `file` from an earlier run, if it is usable. An unreadable or foreign file, or one
// that lacks what the study needs (CellFileRule::lacks), is computed again (a truncated write,
// an edited file) and said so in `notes`; one made with other
// settings is refused (InputError naming the file) unless rule.redo_other_settings.
template <class Cell>
std::optional<Cell> read_previous_cell(const std::filesystem::path& file,
                                       const CellFileRule<Cell>& rule, Progress& notes) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return std::nullopt;
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
    if (cell.settings == rule.settings) {
        const std::string lacking = rule.lacks ? rule.lacks(cell) : "";
        if (lacking.empty()) return cell;
        notes.note("the file holds " + lacking + "; computing it again");
        return std::nullopt;
    }
    if (rule.redo_other_settings) {
        notes.note("made with other settings; computing it again");
        return std::nullopt;
    }
    throw InputError(file.string(),
                     fmt::format("made with other settings ({}); use another output folder, or "
                                 "--redo to compute such cells again",
                                 settings_difference(cell.settings, rule.settings)));
}

// A study's cells, in order, and what it does with each.
template <class Cell>
struct CellLoop {
    std::size_t count = 0;
    std::function<std::optional<Cell>(std::size_t)> previous;  // read_previous_cell's answer
    // Computes a cell, writing its files (images, meshes) through the batch: they go into place
    // with the cell's file, or not at all.
    std::function<Cell(std::size_t, FileBatch&)> compute;
    std::function<nlohmann::json(const Cell&)> to_json;
    std::function<Cell(const nlohmann::json&)> from_json;
    std::function<std::filesystem::path(std::size_t)> file;
    std::function<std::vector<std::filesystem::path>(std::size_t)> outputs;  // file() and more
    std::function<std::string(std::size_t)> where;                           // "[3/21] CELL"
    std::function<std::string(const Cell&)> outcome;  // "done", "failed", ...
};

// One cell, before any is computed: its outputs checked (common/output_paths.h: none a folder, a
// device or a name too long), each folder they go into proven writable once (`folders` holds
// those already proven: common/output_set.h), and its earlier file read (CellLoop::previous),
// so that a refusal loses no work. Throws InputError for the first output that cannot be
// written.
template <class Cell>
std::optional<Cell> check_cell(const CellLoop<Cell>& loop, std::size_t i,
                               std::set<std::filesystem::path>& folders) {
    for (const std::filesystem::path& file : loop.outputs(i)) {
        check_output_file(file);
        if (folders.insert(file.parent_path()).second) check_folder_takes(file);
    }
    return loop.previous(i);
}

// Computes cell i and puts its files into place together, its cell file among them: an error
// or a signal on the way leaves none of them. Returns the cell as its file holds it.
template <class Cell>
nlohmann::json compute_cell(const CellLoop<Cell>& loop, std::size_t i) {
    FileBatch files;
    nlohmann::json j = loop.to_json(loop.compute(i, files));
    write_text_atomically(files.temp(loop.file(i)), j.dump(2) + "\n");
    files.commit();
    return j;
}

// Every cell is checked first (check_cell); a usable earlier one is skipped, the others are
// computed, written with their files (compute_cell) and taken back as a resumed run would read
// them. A note after
// each cell: its outcome, the time elapsed and the time left from the cells computed so far.
// Throws Interrupted between cells after a signal.
template <class Cell>
std::vector<Cell> run_cells(const CellLoop<Cell>& loop, Progress& progress) {
    std::vector<std::optional<Cell>> previous;
    std::size_t to_compute = 0, computed = 0;
    std::set<std::filesystem::path> folders;
    for (std::size_t i = 0; i < loop.count; ++i) {
        throw_if_interrupted();
        previous.push_back(check_cell(loop, i, folders));
        to_compute += previous.back() ? 0 : 1;
    }
    const auto start = std::chrono::steady_clock::now();
    double compute_seconds = 0;
    std::vector<Cell> cells;
    for (std::size_t i = 0; i < loop.count; ++i) {
        if (previous[i]) {
            cells.push_back(*previous[i]);
            progress.note(loop.where(i) + ": done before, skipped");
            continue;
        }
        throw_if_interrupted();
        const auto cell_start = std::chrono::steady_clock::now();
        const nlohmann::json j = compute_cell(loop, i);
        cells.push_back(loop.from_json(j));
        compute_seconds += seconds_since(cell_start);
        ++computed;
        const double left = compute_seconds / double(computed) * double(to_compute - computed);
        progress.note(fmt::format("{}: {} ({:.0f} s elapsed, about {:.0f} s left)", loop.where(i),
                                  loop.outcome(cells.back()), seconds_since(start), left));
    }
    return cells;
}

}  // namespace hmcr
