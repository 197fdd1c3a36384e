// The `render` and `reference` commands (the study tools of SPEC section 6); cli.cpp wires them.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "studies/reference.h"
#include "studies/study.h"
#include "viz/renderer.h"

namespace hmcr {

// A count written 10000000, 1e7 or 2.5e6: whole numbers only, else nothing.
std::optional<std::uint64_t> parse_count(const std::string& text);
// The option check built on it (rewrites the text to plain digits for CLI11).
const CLI::Validator& count_notation();

struct RenderArgs {
    std::string solution;      // .vtp
    std::string scene;         // for the view
    std::string view;          // empty: the scene's first view
    std::string output;        // .png
    std::string pfm;           // optional linear image
    std::string reference;     // optional reference folder: its exposure for this view
    double exposure = 0;       // > 0: fixed exposure
    RenderOptions options;
};

struct ReferenceArgs {
    std::string scene;
    std::string output;
    ReferenceOptions options;
    bool quiet = false;
};

struct StudyArgs {
    StudyOptions options;
    std::string budgets;  // "2000,5000,19000"
    std::string oracles = "all";
    bool quiet = false;
};

struct InfoArgs {
    std::string scene;           // a scene, or a solution's .vtp
    std::string solution_scene;  // with a .vtp: the scene's name, for the report
    std::string method = "local";  // local or global lines
    std::uint64_t lines = 1'000'000;
    std::uint64_t seed = 1;
    bool json = false;
};

CLI::App* add_info_command(CLI::App& app, InfoArgs& args);
int run_info(const InfoArgs& args);
CLI::App* add_render_command(CLI::App& app, RenderArgs& args);
CLI::App* add_study_command(CLI::App& app, StudyArgs& args);
int run_study_command(StudyArgs& args);
CLI::App* add_reference_command(CLI::App& app, ReferenceArgs& args);
int run_render(const RenderArgs& args);
int run_reference(const ReferenceArgs& args, const std::string& command_line);

}  // namespace hmcr
