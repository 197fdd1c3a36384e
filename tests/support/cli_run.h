// SPDX-License-Identifier: Apache-2.0
// Running the hmcr binary as a user does, and checking what it left behind.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include "tests/support/temp_dir.h"

namespace hmcr::test {

struct CliRun {
    int exit_code = -1;  // 137: killed after the time limit (a hang)
    std::string out, err;
};

// `launcher` hmcr ARGS in `dir`, killed after `seconds`.
inline CliRun run_launched(const std::string& launcher, const std::string& args,
                           const std::filesystem::path& dir, int seconds) {
    const std::string cmd = "cd '" + dir.string() + "' && timeout -s KILL " +
                            std::to_string(seconds) + " " + launcher + std::string(HMCR_BINARY) +
                            " " + args + " >.stdout 2>.stderr";
    const int status = std::system(cmd.c_str());
    CliRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(dir / ".stdout"),
             read_file(dir / ".stderr")};
    std::filesystem::remove(dir / ".stdout");
    std::filesystem::remove(dir / ".stderr");
    return r;
}

// hmcr ARGS in `dir`, killed after `seconds`.
inline CliRun run_hmcr(const std::string& args, const std::filesystem::path& dir,
                       int seconds = 60) {
    return run_launched("", args, dir, seconds);
}

// `mpirun -n RANKS hmcr ARGS`. Open MPI refuses root without its two variables (CI runs as
// root); oversubscribing lets 3 ranks share 2 cores; the single-copy mechanism needs ptrace,
// which containers often forbid.
inline std::string mpirun_prefix(int ranks) {
    return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
           "OMPI_MCA_btl_vader_single_copy_mechanism=none mpirun --oversubscribe -n " +
           std::to_string(ranks) + " ";
}

inline CliRun run_hmcr_mpi(int ranks, const std::string& args, const std::filesystem::path& dir,
                           int seconds = 120) {
    return run_launched("env " + mpirun_prefix(ranks), args, dir, seconds);
}

// Every file below a folder with its bytes: equal snapshots mean nothing was written, removed
// or changed.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        if (e.is_regular_file())
            files[e.path().lexically_relative(dir).string()] = read_file(e.path());
    }
    return files;
}

// The cell files a study has finished in `dir` (each is written whole or not at all).
inline std::size_t finished_cells(const std::filesystem::path& dir) {
    std::size_t n = 0;
    if (!std::filesystem::exists(dir / "cells")) return 0;
    for (const auto& e : std::filesystem::directory_iterator(dir / "cells")) {
        n += e.path().extension() == ".json";
    }
    return n;
}

}  // namespace hmcr::test
