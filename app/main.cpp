// hmcr: the command line. Exit codes: 0 done, 2 bad input (anything the user can fix, said in
// one line on stderr), 1 a fault of hmcr.
#include <fmt/core.h>

#include <vector>

#include "app/command.h"
#include "common/error.h"
#include "common/interrupt.h"

namespace {

std::string join_args(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
    return s;
}

int fail(int code, const std::string& message) {
    fmt::print(stderr, "hmcr: error: {}\n", message);
    return code;
}

int run(const hmcr::Command& command) {
    try {
        return command.run();
    } catch (const hmcr::InputError& e) {
        return fail(2, e.what());
    } catch (const hmcr::Interrupted& e) {
        // What was complete is kept (a study's cells); nothing partial is left.
        return fail(128 + e.signal(), std::string(e.what()) + "; no partial output left");
    } catch (const std::exception& e) {
        return fail(1, std::string("internal error: ") + e.what());
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace hmcr;
    CLI::App app{"hmcr: hierarchical Monte Carlo radiosity with information-theoretic refinement"};
    app.set_version_flag("--version", std::string("hmcr ") + HMCR_VERSION);
    app.require_subcommand(1);
    const std::string command_line = join_args(argc, argv);
    install_interrupt_handlers();
    const std::vector<Command> commands = {solve_command(app, command_line),
                                           render_command(app),
                                           reference_command(app, command_line),
                                           study_command(app),
                                           info_command(app),
                                           oracles_command(app),
                                           scenes_command(app),
                                           trace_command(app, command_line),
                                           samplers_command(app),
                                           trace_reference_command(app, command_line)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(2, std::string(e.what()) + " (see hmcr --help)");
    }
    for (const Command& c : commands) {
        if (c.cli->parsed()) return run(c);
    }
    return fail(1, "internal error: no command ran");
}
