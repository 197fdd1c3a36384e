// SPDX-License-Identifier: Apache-2.0
// Wall-clock seconds, for run summaries, study cells and progress.
#pragma once

#include <chrono>

namespace hmcr {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hmcr
