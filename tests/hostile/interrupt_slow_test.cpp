// SPDX-License-Identifier: Apache-2.0
// Ctrl-C or a cluster's SIGTERM ends a long solve, reference or trace cleanly: exit code
// 128 + signal, one line saying so, and no file left behind (no partial output, no temporary file).
#include <signal.h>
#include <sys/wait.h>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

class Interrupt : public Hostile, public testing::WithParamInterface<int> {};

TEST_P(Interrupt, ALongSolveEndsCleanly) {
    const int signal = GetParam();
    const auto before = snapshot(dir());
    const int status = interrupted("solve cube-room --rays 1e9 -o out/room.vtp --progress none",
                                   dir(), signal, std::chrono::milliseconds(1500));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    const std::string err = read_file(dir() / ".stderr");
    EXPECT_NE(err.find("hmcr: error: interrupted by SIG"), std::string::npos) << err;
    std::filesystem::remove(dir() / ".stdout");
    std::filesystem::remove(dir() / ".stderr");
    EXPECT_TRUE(snapshot(dir()) == before);
}

TEST_P(Interrupt, AReferenceEndsCleanly) {
    const int signal = GetParam();
    const int status = interrupted("reference cube-room --max-area 0.01 --rays 1e9 -o ref -q",
                                   dir(), signal, std::chrono::milliseconds(1500));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    std::filesystem::remove(dir() / ".stdout");
    std::filesystem::remove(dir() / ".stderr");
    EXPECT_TRUE(std::filesystem::is_empty(dir()));  // not even the folder it made
}

TEST_P(Interrupt, ATraceEndsCleanly) {
    const int signal = GetParam();
    const int status = interrupted(
        "trace cube-room --spp 100000 -o out/room.png --pfm out/room.pfm "
        "--progress none",
        dir(), signal, std::chrono::milliseconds(1500));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    EXPECT_NE(read_file(dir() / ".stderr").find("interrupted by SIG"), std::string::npos);
    std::filesystem::remove(dir() / ".stdout");
    std::filesystem::remove(dir() / ".stderr");
    EXPECT_TRUE(snapshot(dir()).empty());
}

INSTANTIATE_TEST_SUITE_P(Signals, Interrupt, testing::Values(SIGINT, SIGTERM),
                         [](const testing::TestParamInfo<int>& p) {
                             return std::string(p.param == SIGINT ? "SIGINT" : "SIGTERM");
                         });

}  // namespace
}  // namespace hmcr::test
