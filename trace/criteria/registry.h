// SPDX-License-Identifier: Apache-2.0
// The pixel sampling criteria by name (`hmcr samplers`, `--sampler NAME`), a Registry of
// common/registry.h.
#pragma once

#include "common/registry.h"
#include "trace/criteria/criterion.h"

namespace hmcr {

// Every pixel criterion (trace/criteria/registry.cpp: one line per criterion).
const Registry<Criterion>& criterion_registry();

// The uniform sampler: the default, and the reference's.
const Criterion& uniform_criterion();

}  // namespace hmcr
