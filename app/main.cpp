// SPDX-License-Identifier: Apache-2.0
// hmcr: the command line. Exit codes: 0 done, 2 bad input (anything the user can fix, said in
// one line on stderr), 1 a fault of hmcr.
#include <fmt/core.h>

#include <cstdio>
#include <vector>

#include "app/command.h"
#include "app/count.h"
#include "common/error.h"
#include "common/exit_code.h"
#include "common/interrupt.h"
#include "common/ranks.h"

namespace {

std::string join_args(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
    return s;
}

// Rank 0 speaks for an MPI run: a failure anywhere reaches it (Ranks::agree, the study's
// hand-out), so one message is printed, not one per rank.
int fail(int code, const std::string& message) {
    if (hmcr::Ranks::world().root()) fmt::print(stderr, "hmcr: error: {}\n", message);
    return code;
}

int run(const hmcr::Command& command) {
    try {
        return command.run();
    } catch (...) {
        const hmcr::Failure f = hmcr::failure_of(std::current_exception());
        return fail(f.exit_code, f.message);
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace hmcr;
    const MpiSession mpi(argc, argv);
    // Rank 0 speaks for the run (progress, warnings, reports and the one error message); the
    // others would only repeat it.
    if (!Ranks::world().root()) {
        if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)) {
            return 1;
        }
    }
    CLI::App app{"hmcr: hierarchical Monte Carlo radiosity with information-theoretic refinement"};
    app.set_version_flag("--version", std::string("hmcr ") + HMCR_VERSION);
    app.require_subcommand(1);
    const std::string command_line = join_args(argc, argv);
    install_interrupt_handlers();
    const std::vector<Command> commands = {solve_command(app, command_line),
                                           render_command(app),
                                           reference_command(app, command_line),
                                           error_command(app),
                                           study_command(app),
                                           plot_command(app),
                                           info_command(app),
                                           oracles_command(app),
                                           scenes_command(app),
                                           trace_command(app, command_line),
                                           samplers_command(app),
                                           trace_reference_command(app, command_line)};
    require_finite_reals(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(2, std::string(e.what()) + " (see hmcr --help)");
    } catch (const InputError& e) {  // a name resolved where it is read: --oracle, --sampler
        return fail(2, e.what());
    }
    for (const Command& c : commands) {
        if (!c.cli->parsed()) continue;
        // Under mpirun a command that does not share its work runs once, not once per rank.
        if (!c.over_ranks && !Ranks::world().root()) return 0;
        return run(c);
    }
    return fail(1, "internal error: no command ran");
}
