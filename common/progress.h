// SPDX-License-Identifier: Apache-2.0
// Progress of a long task: told by the code doing the work (a solve, a reference, a study, the
// scene measures) and shown by the front end (app/ draws a bar or prints lines). Calls come from
// the thread that started the task.
#pragma once

#include <string>
#include <string_view>

namespace hmcr {

class Progress {
public:
    virtual ~Progress() = default;
    // A new stage of the task (a solve, a budget probe, a study cell): the fraction restarts.
    virtual void stage(std::string_view label) = 0;
    // The fraction of the current stage done, in [0, 1].
    virtual void advance(double fraction) = 0;
    // One line of news about the task (a probe's result, a cell done).
    virtual void note(std::string_view line) = 0;
};

// Shows nothing: for tests, and for work that is part of a larger task.
Progress& no_progress();

// Passes everything on to `outer` with `prefix` before every stage label and note: for a task
// that is one part of a larger one ("view camera: tracing").
class PrefixedProgress final : public Progress {
public:
    PrefixedProgress(Progress& outer, std::string prefix)
        : m_outer(outer), m_prefix(std::move(prefix)) {}
    void stage(std::string_view label) override { m_outer.stage(m_prefix + std::string(label)); }
    void advance(double fraction) override { m_outer.advance(fraction); }
    void note(std::string_view line) override { m_outer.note(m_prefix + std::string(line)); }

private:
    Progress& m_outer;
    std::string m_prefix;
};

}  // namespace hmcr
