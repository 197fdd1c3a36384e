// SPDX-License-Identifier: Apache-2.0
#include "app/terminal_progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

#include "common/error.h"
#include "common/stopwatch.h"

namespace hmcr {

ProgressMode progress_mode_for(const std::string& requested, bool quiet) {
    if (quiet || requested == "none") return ProgressMode::none;
    if (requested == "bar") return ProgressMode::bar;
    if (requested == "lines") return ProgressMode::lines;
    if (requested == "auto") return isatty(STDERR_FILENO) ? ProgressMode::bar : ProgressMode::lines;
    throw InputError("progress must be auto, bar, lines or none, got " + quote(requested));
}

TerminalProgress::TerminalProgress(ProgressMode mode, std::string label)
    : m_mode(mode), m_label(std::move(label)) {}

std::string TerminalProgress::prefix() const {
    return m_stage.empty() ? m_label : m_label + ": " + m_stage;
}

void TerminalProgress::stage(std::string_view label) {
    end_bar();
    m_stage = label;
    m_last_decile = 0;
    m_last_percent = -1;
    m_last_line = 0;
    m_start = std::chrono::steady_clock::now();
}

void TerminalProgress::advance(double fraction) {
    const double elapsed = seconds_since(m_start);
    const int percent = int(fraction * 100);
    if (m_mode == ProgressMode::bar && percent != m_last_percent) {
        m_last_percent = percent;
        const int filled = percent * 30 / 100;
        const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
        fmt::print(stderr, "\r{} [{:<30}] {:3d}%  {:.1f} s, ~{:.0f} s left ", prefix(),
                   std::string(std::size_t(filled), '#'), percent, elapsed, eta);
        std::fflush(stderr);
        m_bar_open = true;
    } else if (m_mode == ProgressMode::lines &&
               (percent / 10 > m_last_decile || elapsed - m_last_line > kLinePeriod)) {
        // Every 10%, and every half minute in between: a long run says how long it will take.
        m_last_decile = percent / 10;
        m_last_line = elapsed;
        const std::string left =
            fraction > 0 && fraction < 1
                ? fmt::format(", about {:.0f} s left", elapsed * (1 - fraction) / fraction)
                : std::string();
        fmt::print(stderr, "{}: {}%, {:.1f} s{}\n", prefix(), percent, elapsed, left);
    }
}

void TerminalProgress::note(std::string_view line) {
    if (m_mode == ProgressMode::none) return;
    end_bar();
    fmt::print(stderr, "{}: {}\n", m_label, line);
}

void TerminalProgress::end_bar() {
    if (!m_bar_open) return;
    fmt::print(stderr, "\n");
    m_bar_open = false;
}

}  // namespace hmcr
