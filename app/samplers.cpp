// SPDX-License-Identifier: Apache-2.0
// `hmcr samplers`: the registered pixel sampling criteria.
#include <fmt/core.h>

#include "app/command.h"
#include "trace/criteria/registry.h"

namespace hmcr {

Command samplers_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("samplers", "list the pixel sampling criteria of `trace`");
    return {cmd, [] {
                for (const Criterion* c : criterion_registry().all()) {
                    fmt::print("{:<15} {}\n", c->name(), c->description());
                }
                return 0;
            }};
}

}  // namespace hmcr
