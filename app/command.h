// SPDX-License-Identifier: Apache-2.0
// The subcommands of `hmcr`. Each file of app/ adds one to the CLI11 application: its options,
// bound to state that its run function owns, and the run function, called when the user chose
// it. Errors are exceptions (common/error.h); main.cpp turns them into exit codes.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace hmcr {

struct Command {
    CLI::App* cli = nullptr;
    std::function<int()> run;
    // Shares its work over MPI ranks (docs/cluster.md); the others run on rank 0 alone.
    bool over_ranks = false;
};

// `command_line` is the whole invocation, recorded in run summaries.
Command solve_command(CLI::App& app, const std::string& command_line);
Command render_command(CLI::App& app);
Command reference_command(CLI::App& app, const std::string& command_line);
Command error_command(CLI::App& app);
Command study_command(CLI::App& app);
Command plot_command(CLI::App& app);
Command info_command(CLI::App& app);
Command oracles_command(CLI::App& app);
Command scenes_command(CLI::App& app);
Command trace_command(CLI::App& app, const std::string& command_line);
Command samplers_command(CLI::App& app);
Command trace_reference_command(CLI::App& app, const std::string& command_line);

}  // namespace hmcr
