// SPDX-License-Identifier: Apache-2.0
// An interrupted study loses at most the cell in flight: `hmcr study` is killed (SIGKILL) or
// asked to stop (SIGTERM, SIGINT) after its first cell is written, then run again; the rerun
// skips every cell the first run finished and completes the rest. Asked to stop, it ends with
// exit code 128 + signal and leaves no temporary file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

std::size_t temp_files(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        n += e.path().string().find(".tmp.") != std::string::npos;
    }
    return n;
}

class StudyKill : public testing::TestWithParam<int> {};

TEST_P(StudyKill, RerunSkipsTheFinishedCellsAndCompletesTheRest) {
    const int signal = GetParam();
    TempDir dir;
    const fs::path ref = dir.path() / "ref", out = dir.path() / "study";
    ASSERT_EQ(run_hmcr("reference plates --max-area 0.05 --rays 20000 -q -o " + ref.string(),
                       dir.path(), 600)
                  .exit_code,
              0);
    const std::string study = "study plates --reference " + ref.string() +
                              " --budgets 60,120 --oracles power,kl --seeds 2 --rays 400000 -o " +
                              out.string();
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        execl(
            "/bin/sh", "sh", "-c",
            (std::string("exec ") + HMCR_BINARY + " " + study + " >/dev/null 2>/dev/null").c_str(),
            nullptr);
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (finished_cells(out) == 0 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(child, signal);
    int status = 0;
    waitpid(child, &status, 0);
    if (signal != SIGKILL) {
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
        EXPECT_EQ(temp_files(out), 0u);
    }
    const std::size_t before = finished_cells(out);
    ASSERT_GE(before, 1u);
    ASSERT_LT(before, 8u) << "the study finished before it could be killed";
    EXPECT_FALSE(fs::exists(out / "table.md"));

    const CliRun rerun = run_hmcr(study, dir.path(), 600);
    ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
    const std::string& log = rerun.err;
    std::size_t skipped = 0;
    for (std::size_t at = 0; (at = log.find("done before, skipped", at)) != std::string::npos;
         ++at) {
        ++skipped;
    }
    EXPECT_EQ(skipped, before) << log;
    EXPECT_EQ(finished_cells(out), 8u);
    EXPECT_TRUE(fs::exists(out / "table.md"));
}

INSTANTIATE_TEST_SUITE_P(Signals, StudyKill, testing::Values(SIGKILL, SIGTERM, SIGINT),
                         [](const testing::TestParamInfo<int>& p) {
                             return std::string(p.param == SIGKILL   ? "SIGKILL"
                                                : p.param == SIGTERM ? "SIGTERM"
                                                                     : "SIGINT");
                         });

}  // namespace
}  // namespace hmcr::test
