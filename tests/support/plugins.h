// SPDX-License-Identifier: Apache-2.0
// The registered plug-ins by name, for tests that name them (parameters, options).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/error.h"
#include "radiosity/oracle_registry.h"
#include "trace/criteria/registry.h"

namespace hmcr::test {

inline const Oracle* oracle(std::string_view name) { return &find_named(oracle_registry(), name); }
inline const Criterion* criterion(std::string_view name) {
    return &find_named(criterion_registry(), name);
}

// Every registered oracle's name, in registry order: the parameters of a suite run per oracle.
inline std::vector<std::string> oracle_name_list() {
    std::vector<std::string> names;
    for (const Oracle* o : oracle_registry().all()) names.emplace_back(o->name());
    return names;
}

}  // namespace hmcr::test
