// SPDX-License-Identifier: Apache-2.0
// `hmcr oracles`: the registered refinement oracles.
#include <fmt/core.h>

#include "app/command.h"
#include "radiosity/oracle_registry.h"

namespace hmcr {

Command oracles_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("oracles", "list the refinement oracles");
    return {cmd, [] {
                for (const Oracle* o : oracle_registry().all()) {
                    fmt::print("{:<8} {} (default epsilon {:g})\n", o->name(), o->description(),
                               o->default_epsilon());
                }
                return 0;
            }};
}

}  // namespace hmcr
