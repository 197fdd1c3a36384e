// Running the hmcr binary as a user does, for the command-line tests.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/temp_dir.h"

namespace hmcr::test {

struct CliRun {
    int exit_code = -1;
    std::string out, err;
};

// `hmcr ARGS`, its stdout and stderr kept in files of `dir`.
inline CliRun run_hmcr(const std::string& args, const std::filesystem::path& dir) {
    const std::string cmd = std::string(HMCR_BINARY) + " " + args + " >" +
                            (dir / "stdout").string() + " 2>" + (dir / "stderr").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(dir / "stdout"),
            read_file(dir / "stderr")};
}

}  // namespace hmcr::test
