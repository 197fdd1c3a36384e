// SPDX-License-Identifier: Apache-2.0
// Where hmcr finds the files it ships beside the program: the bundled scenes (scenes/) and the
// plotting script of the studies (scripts/plot_study.py). An install (`cmake --install`) puts
// them in PREFIX/share/hmcr/ and the program in PREFIX/bin/; the source tree has the same layout
// of these files, so a program run from its build folder uses the source tree.
#pragma once

#include <filesystem>

namespace hmcr {

// The environment variable that names the data directory, overriding the rules below.
inline constexpr const char* kDataDirVariable = "HMCR_DATA_DIR";

// $HMCR_DATA_DIR when set; else BIN/../share/hmcr when it exists beside the executable's folder
// BIN (an install); else the source tree when the executable lies in the build folder it was
// built in; else BIN/../share/hmcr all the same, for messages to name.
std::filesystem::path data_directory();

}  // namespace hmcr
