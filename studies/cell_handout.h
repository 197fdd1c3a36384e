// SPDX-License-Identifier: Apache-2.0
// A study's cells over MPI ranks (docs/cluster.md): rank 0 reads what earlier runs left, then
// hands out the cells still to compute, one at a time, to ranks 1..K-1 as they become free.
// Each worker writes its cells atomically, as a single process does, so a run killed on any
// rank loses at most the cells in flight, and a rerun with any K resumes. Rank 0 only hands out
// and collects (its answers take microseconds between cells of seconds or minutes); it alone
// returns the cells, to write the tables.
//
// A failed cell (an error, a signal) stops the hand-out: the cells in flight finish and are
// kept, then every rank ends and rank 0 reports the failure.
#pragma once

#include <string>
#include <vector>

#include "common/exit_code.h"
#include "common/ranks.h"
#include "studies/cell_files.h"

namespace hmcr {

namespace handout {
inline constexpr int kWork = 1;  // rank 0 to a worker: a cell index, or nothing: stop
inline constexpr int kDone = 2;  // a worker to rank 0: "index\njson", or "!code message"
}  // namespace handout

template <class Cell>
std::vector<Cell> hand_out_cells(const CellLoop<Cell>& loop, Progress& progress,
                                 const Ranks& ranks) {
    const auto stop_all = [&] {
        for (int r = 1; r < ranks.size(); ++r) ranks.send(r, handout::kWork, "");
    };
    std::vector<std::optional<Cell>> cells(loop.count);
    std::vector<std::size_t> todo;
    std::set<std::filesystem::path> folders;
    try {
        for (std::size_t i = 0; i < loop.count; ++i) {
            throw_if_interrupted();
            cells[i] = check_cell(loop, i, folders);
            if (!cells[i]) todo.push_back(i);
        }
    } catch (...) {
        stop_all();
        throw;
    }
    for (std::size_t i = 0; i < loop.count; ++i) {
        if (cells[i]) progress.note(loop.where(i) + ": done before, skipped");
    }
    const auto start = std::chrono::steady_clock::now();
    std::size_t next = 0, computed = 0;
    int active = 0;
    std::optional<Failure> failure;
    const auto hand_to = [&](int rank) {
        if (!failure && next < todo.size()) {
            ranks.send(rank, handout::kWork, std::to_string(todo[next++]));
            ++active;
        } else {
            ranks.send(rank, handout::kWork, "");
        }
    };
    const auto notice_signal = [&] {
        try {
            throw_if_interrupted();
        } catch (...) {
            if (!failure) failure = failure_of(std::current_exception());
        }
    };
    for (int r = 1; r < ranks.size(); ++r) hand_to(r);
    while (active > 0) {
        const auto [from, message] = ranks.receive_any(handout::kDone, notice_signal);
        --active;
        if (message.starts_with("!")) {
            const std::size_t space = message.find(' ');
            if (!failure)
                failure =
                    Failure{std::stoi(message.substr(1, space - 1)), message.substr(space + 1)};
        } else {
            const std::size_t eol = message.find('\n');
            const std::size_t i = std::stoull(message.substr(0, eol));
            cells[i] = loop.from_json(nlohmann::json::parse(message.substr(eol + 1)));
            ++computed;
            const double elapsed = seconds_since(start);
            const double left = elapsed / double(computed) * double(todo.size() - computed);
            progress.note(fmt::format("{}: {} (rank {}; {:.0f} s elapsed, about {:.0f} s left)",
                                      loop.where(i), loop.outcome(*cells[i]), from, elapsed, left));
        }
        hand_to(from);
    }
    if (failure) throw OtherRankFailed(failure->message, failure->exit_code);
    std::vector<Cell> out;
    out.reserve(cells.size());
    for (auto& c : cells) out.push_back(std::move(*c));
    return out;
}

template <class Cell>
void work_on_cells(const CellLoop<Cell>& loop, const Ranks& ranks) {
    for (;;) {
        const std::string work = ranks.receive(0, handout::kWork);
        if (work.empty()) return;
        const std::size_t i = std::stoull(work);
        try {
            const nlohmann::json j = compute_cell(loop, i);
            ranks.send(0, handout::kDone, std::to_string(i) + "\n" + j.dump(2) + "\n");
        } catch (...) {
            const Failure f = failure_of(std::current_exception());
            ranks.send(0, handout::kDone, "!" + std::to_string(f.exit_code) + " " + f.message);
        }
    }
}

// run_cells (cell_files.h) on one process, or over `ranks`; only rank 0 gets the cells.
template <class Cell>
std::vector<Cell> run_cells_on(const Ranks& ranks, const CellLoop<Cell>& loop, Progress& progress) {
    if (ranks.size() == 1) return run_cells(loop, progress);
    if (ranks.root()) return hand_out_cells(loop, progress, ranks);
    work_on_cells(loop, ranks);
    return {};
}

}  // namespace hmcr
