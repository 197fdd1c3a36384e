#include "app/terminal_progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace hmcr {

ProgressMode progress_mode_for(const std::string& requested, bool quiet) {
    if (quiet || requested == "none") return ProgressMode::none;
    if (requested == "bar") return ProgressMode::bar;
    if (requested == "lines") return ProgressMode::lines;
    if (requested == "auto") return isatty(STDERR_FILENO) ? ProgressMode::bar : ProgressMode::lines;
    throw std::invalid_argument("progress must be auto, bar, lines or none, got '" + requested + "'");
}

ProgressReporter::ProgressReporter(ProgressMode mode, std::string label)
    : m_mode(mode), m_label(std::move(label)) {}

void ProgressReporter::update(double fraction) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const int percent = int(fraction * 100);
    if (m_mode == ProgressMode::bar && percent != m_last_percent) {
        m_last_percent = percent;
        const int filled = percent * 30 / 100;
        const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
        fmt::print(stderr, "\r{} [{:<30}] {:3d}%  {:.1f} s, ~{:.0f} s left ", m_label,
                   std::string(std::size_t(filled), '#'), percent, elapsed, eta);
        std::fflush(stderr);
    } else if (m_mode == ProgressMode::lines && percent / 10 > m_last_decile) {
        m_last_decile = percent / 10;
        fmt::print(stderr, "{}: {}% of the rays shot, {:.1f} s\n", m_label, m_last_decile * 10,
                   elapsed);
    }
}

void ProgressReporter::finish() {
    if (m_mode == ProgressMode::bar) fmt::print(stderr, "\n");
}

void ProgressReporter::restart() {
    m_last_decile = 0;
    m_last_percent = -1;
    m_start = std::chrono::steady_clock::now();
}

}  // namespace hmcr
