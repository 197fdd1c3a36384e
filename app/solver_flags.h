// SPDX-License-Identifier: Apache-2.0
// The solver settings table (radiosity/solver_options.h) on the command line: one flag per
// setting, with its help and default, and the rule that decides each setting's value.
#pragma once

#include <CLI/CLI.hpp>
#include <set>
#include <string>

#include "meshes/scene.h"
#include "radiosity/solver_options.h"

namespace hmcr {

// The flags a command took from the table, bound to its options.
struct SolverFlags {
    CLI::App* command = nullptr;
    std::set<std::string> names;       // settings with a flag on this command
    std::set<std::string> from_scene;  // of which a scene file may set the value
};

// Adds a flag for every command-line or scene-file setting except those in `except` (a study
// sets oracle, epsilon and seed per cell). The defaults shown are the values in `options`.
// Settings in `not_from_scene` are this command's own (a reference's rays are not a solve's).
SolverFlags add_solver_flags(CLI::App& command, SolverOptions& options,
                             const std::set<std::string>& except = {},
                             const std::set<std::string>& not_from_scene = {});

// Every flagged setting not given on the command line takes the scene file's value, if it has
// one. The scene file's settings are checked whether or not they are overridden; then all of
// `options` is.
void apply_scene_settings(const SolverFlags& flags, const Scene& scene, SolverOptions& options);

}  // namespace hmcr
