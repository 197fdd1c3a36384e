// SPDX-License-Identifier: Apache-2.0
// An RGB triple in JSON files (summaries, reference.json): [r, g, b].
#pragma once

#include <nlohmann/json.hpp>

#include "common/types.h"

namespace hmcr {

inline nlohmann::json rgb_json(const Rgb& c) { return {c[0], c[1], c[2]}; }

}  // namespace hmcr
