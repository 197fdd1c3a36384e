// SPDX-License-Identifier: Apache-2.0
// The refinement oracles by name (`hmcr oracles`, `--oracle NAME`), a Registry of
// common/registry.h.
#pragma once

#include "common/registry.h"
#include "oracles/oracle.h"

namespace hmcr {

// Every refinement oracle (radiosity/oracle_registry.cpp: one line per oracle).
const Registry<Oracle>& oracle_registry();

}  // namespace hmcr
