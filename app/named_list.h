// SPDX-License-Identifier: Apache-2.0
// A comma-separated list of plug-in names on the command line (`--oracles kl,power`,
// `--samplers all`), resolved where it is read.
#pragma once

#include <string>
#include <vector>

#include "common/error.h"

namespace hmcr {

// The plug-ins of `registry` that `names` give, in their order; "all" stands for every one.
// Throws InputError for a name the registry does not hold.
template <class Registry>
auto named_list(const Registry& registry, const std::vector<std::string>& names) {
    auto out = registry.all();
    out.clear();
    for (const std::string& name : names) {
        if (name == "all") {
            out.insert(out.end(), registry.all().begin(), registry.all().end());
        } else {
            out.push_back(&find_named(registry, name));
        }
    }
    return out;
}

}  // namespace hmcr
