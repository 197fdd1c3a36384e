// SPDX-License-Identifier: Apache-2.0
// `hmcr plot STUDY`: a study's plots drawn again from its table.json (studies/plot_data.h),
// into STUDY/plots/: after installing matplotlib, or after changing the plotting script.
#include <fmt/core.h>

#include <memory>

#include "app/command.h"
#include "app/plot_script.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/output_set.h"
#include "studies/plot_data.h"

namespace hmcr {
namespace {

struct PlotArgs {
    std::filesystem::path study;
    bool quiet = false;
};

int run_plot(const PlotArgs& a) {
    // Everything is checked before anything is written.
    const nlohmann::json data = plot_data_of_table(a.study / "table.json");
    const std::optional<std::string> python = plotting_python();
    if (const std::string why = why_no_plots(python, a.study); !why.empty()) {
        throw InputError("plot: " + why);
    }
    // The plot data is written as a set of one, with the study folder locked against a study
    // still writing it (common/output_set.h); the plots are drawn from it.
    const std::filesystem::path file = plot_data_file(a.study);
    OutputSet out({file}, a.study);
    write_text_atomically(out.temp(file), plot_data_text(data));
    out.commit();
    try {
        draw_plots(*python, file);
    } catch (const InputError& e) {
        throw InputError(std::string("plot: ") + e.what());
    }
    if (!a.quiet) fmt::print("plots written to {}\n", (a.study / "plots").string());
    return 0;
}

}  // namespace

Command plot_command(CLI::App& app) {
    auto a = std::make_shared<PlotArgs>();
    auto* cmd = app.add_subcommand(
        "plot", "draw a study's plots again from its table.json (PDF and PNG in STUDY/plots)");
    cmd->add_option("study", a->study, "a study folder (written by `hmcr study`)")->required();
    cmd->add_flag("-q,--quiet", a->quiet, "print only errors");
    return {cmd, [a] { return run_plot(*a); }};
}

}  // namespace hmcr
