// Progress on stderr (SPEC section 5): a live bar on a terminal, a line every 10% otherwise.
#pragma once

#include <chrono>
#include <string>

namespace hmcr {

enum class ProgressMode { none, bar, lines };

// auto: a bar when stderr is a terminal, lines otherwise.
ProgressMode progress_mode_for(const std::string& requested, bool quiet);

class ProgressReporter {
public:
    ProgressReporter(ProgressMode mode, std::string label);
    void update(double fraction);  // in [0, 1]
    void finish();
    void restart();  // a new run of the same task (the next budget probe)

private:
    ProgressMode m_mode;
    std::string m_label;
    int m_last_decile = 0;  // 0% is not worth a line
    int m_last_percent = -1;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

}  // namespace hmcr
