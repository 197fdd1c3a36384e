// SPDX-License-Identifier: Apache-2.0
// A study's plots drawn by scripts/plot_study.py from STUDY/plots/plot_data.json
// (studies/plot_data.h), in a Python that has matplotlib: $HMCR_PYTHON when set, else the first
// of `python3` on the PATH and /usr/bin/python3 that imports it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace hmcr {

// The environment variable that names the Python to draw with.
inline constexpr const char* kPythonVariable = "HMCR_PYTHON";

// The Python to draw with, or nothing when no candidate imports matplotlib.
std::optional<std::string> plotting_python();

// The plotting script, in the data directory (common/data_directory.h).
std::filesystem::path plot_script();

// Why the plots cannot be drawn here, and how to draw them: "" when they can.
std::string why_no_plots(const std::optional<std::string>& python,
                         const std::filesystem::path& study);

// Runs the script on the data file. Throws Interrupted after a signal, InputError when the
// script fails, in one line with the last line the script wrote on stderr (a Python error's
// own message).
void draw_plots(const std::string& python, const std::filesystem::path& data);

// What `hmcr study` does at the end: draws the plots of the study's plot data, or, when they
// cannot be drawn here, says why and how in one warning (unless quiet). A script that fails is
// a warning too, always: the study's tables are written by then.
void draw_study_plots(const std::filesystem::path& study, bool quiet);

}  // namespace hmcr
