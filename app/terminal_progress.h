// SPDX-License-Identifier: Apache-2.0
// Progress on stderr (docs/design.md §5): a live bar on a terminal, a line every 10% otherwise;
// notes are lines in both modes. Every line starts with the task's label ("hmcr cornell").
#pragma once

#include <chrono>
#include <string>

#include "common/progress.h"

namespace hmcr {

enum class ProgressMode { none, bar, lines };

// "auto" (a bar when stderr is a terminal, lines otherwise), "bar", "lines" or "none"; none
// whenever quiet.
ProgressMode progress_mode_for(const std::string& requested, bool quiet);

class TerminalProgress final : public Progress {
public:
    TerminalProgress(ProgressMode mode, std::string label);
    ~TerminalProgress() override { end_bar(); }
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    void stage(std::string_view label) override;
    void advance(double fraction) override;
    void note(std::string_view line) override;

private:
    void end_bar();
    std::string prefix() const;  // "hmcr cornell: budget probe 2"

    ProgressMode m_mode;
    std::string m_label, m_stage;
    int m_last_decile = 0;  // 0% is not worth a line
    int m_last_percent = -1;
    double m_last_line = 0;  // seconds into the stage of the last line printed
    static constexpr double kLinePeriod = 30;
    bool m_bar_open = false;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

}  // namespace hmcr
