// SPDX-License-Identifier: Apache-2.0
// Two runs given the same output at once (a script started twice, two jobs of one array): the
// second is refused while the first holds the output (common/output_lock.h), so the files left
// are always one run's set, never x.vtp of one beside x.json of the other.
#include <sys/ptrace.h>
#include <sys/syscall.h>
#include <sys/uio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <nlohmann/json.hpp>

#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"
#include "viz/solution_file.h"

namespace hmcr::test {
namespace {

// The seed of x.json and of x.vtp in `dir`: equal when both are one run's.
std::pair<std::uint64_t, std::uint64_t> seeds(const std::filesystem::path& dir) {
    const auto summary = nlohmann::json::parse(read_file(dir / "x.json"));
    return {summary["options"]["seed"].get<std::uint64_t>(),
            read_solution(dir / "x.vtp").meta.seed};
}

// Both runs shoot the same rays with their own seed: they finish together, which is when their
// writes would interleave.
TEST_F(Hostile, TwoSolvesOfOneOutputLeaveOneRunsFiles) {
    plates();
    const std::string solve = std::string(HMCR_BINARY) +
                              " solve plates.json --rays 20000 --epsilon 1e-6 -q -o x.vtp --seed ";
    int refusals = 0;
    for (int round = 0; round < 12; ++round) {
        const std::string both = "cd '" + dir().string() + "' && (" + solve + "1 2>.err1 & " +
                                 solve + "2 2>.err2; wait)";
        ASSERT_EQ(std::system(both.c_str()), 0);
        for (const char* err : {".err1", ".err2"}) {
            const std::string text = read_file(dir() / err);
            EXPECT_TRUE(text.empty() ||
                        text.find("another hmcr run is writing it") != std::string::npos)
                << text;
            refusals += !text.empty();
        }
        const auto [summary_seed, solution_seed] = seeds(dir());
        ASSERT_EQ(summary_seed, solution_seed) << "round " << round << ": a mixed set";
    }
    std::cout << refusals << " of 24 runs refused\n";
}

// Waits up to 30 s for `file` to appear: the lock of a run started in the background.
bool appears(const std::filesystem::path& file) {
    for (int i = 0; i < 1500 && !std::filesystem::exists(file); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return std::filesystem::exists(file);
}

// Waits up to 30 s for `file` to appear and the folder `dir` to settle: a run started in the
// background takes its lock, then makes its output's subfolders and tries a file in each, and a
// refusal's check that nothing changed must not see those.
bool appears_and_settles(const std::filesystem::path& file, const std::filesystem::path& dir) {
    if (!appears(file)) return false;
    auto last = snapshot(dir);
    for (int i = 0; i < 300; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        auto now = snapshot(dir);
        if (now == last) return true;
        last = std::move(now);
    }
    return false;
}

// Outputs that nest: a folder being written by one run, a file in it by another. Whichever
// starts second is refused at once, and the first run's files stay its own.
TEST_F(Hostile, ARunIntoAFolderAnotherRunWritesIsRefused) {
    plates();
    // The first run works from bg/, where its .stdout and .stderr are out of the way of the
    // second's.
    const std::filesystem::path bg = dir() / "bg";
    std::filesystem::create_directories(bg);
    {
        HmcrChild solve("solve ../plates.json --rays 1e12 -q -o ../ref/reference.vtp", bg, 60);
        ASSERT_TRUE(appears_and_settles(dir() / "ref" / ".reference.pvsm.lock", dir()));
        refused("reference plates.json -q -o ref",
                "cannot write ref: another hmcr run is writing in it");
        refused("study plates.json --reference elsewhere -q --budgets 5 -o ref",
                "cannot write ref: another hmcr run is writing in it");
        solve.signal(SIGTERM);
        EXPECT_EQ(solve.wait().code, 128 + SIGTERM);
    }
    {
        HmcrChild reference("trace-reference ../plates.json --spp 1e6 -q -o ../ref", bg, 60);
        ASSERT_TRUE(appears_and_settles(dir() / "ref" / ".hmcr.lock", dir()));
        refused("solve plates.json --rays 1000 -q -o ref/reference.vtp",
                "cannot write ref/reference.vtp: another hmcr run is writing the folder");
        refused("solve plates.json --rays 1000 -q -o ref/deeper/x.vtp",
                "cannot write ref/deeper/x.vtp: another hmcr run is writing the folder");
        refused("reference plates.json -q -o ref/views",
                "cannot write ref/views: another hmcr run is writing the folder");
        reference.signal(SIGTERM);
        EXPECT_EQ(reference.wait().code, 128 + SIGTERM);
    }
    EXPECT_FALSE(std::filesystem::exists(dir() / "ref"));  // each run took back what it made
    accepted("solve plates.json --rays 1000 -q -o ref/reference.vtp");  // free again
}

// The first run of the test below, seed 1, into x.vtp in `dir`, under ptrace (exit 126 when
// this process may not trace it).
pid_t start_first_run(const std::filesystem::path& dir) {
    const std::string cmd = "cd '" + dir.string() + "' && exec " + HMCR_BINARY +
                            " solve plates.json --rays 20000 --epsilon 1e-6 -q -o x.vtp "
                            "--seed 1 2>.err1";
    const pid_t child = fork();
    if (child == 0) {
        if (ptrace(PTRACE_TRACEME, 0, nullptr, nullptr) != 0) _exit(126);
        raise(SIGSTOP);  // until the tracer has set its options
        execl("/bin/sh", "sh", "-c", cmd.c_str(), nullptr);
        _exit(127);
    }
    return child;
}

// The path a traced process passes at `address`, read from its memory.
std::string traced_string(pid_t pid, std::uint64_t address) {
    std::string out;
    char chunk[256];
    for (;;) {
        iovec local{chunk, sizeof chunk};
        iovec remote{reinterpret_cast<void*>(address + out.size()), sizeof chunk};
        const ssize_t n = process_vm_readv(pid, &local, 1, &remote, 1, 0);
        if (n <= 0) return out;
        const char* end = static_cast<const char*>(std::memchr(chunk, '\0', std::size_t(n)));
        out.append(chunk, end ? std::size_t(end - chunk) : std::size_t(n));
        if (end || out.size() > 4096) return out;
    }
}

// Runs the traced `child` from one system call to the next until it enters a rename onto a
// file named `name`, where it stays stopped. False if it ends first: `status` is then its
// exit status, the child already reaped.
bool hold_at_rename_onto(pid_t child, const std::string& name, int& status) {
    if (waitpid(child, &status, 0) != child || !WIFSTOPPED(status)) return false;
    ptrace(PTRACE_SETOPTIONS, child, nullptr,
           PTRACE_O_TRACESYSGOOD | PTRACE_O_TRACEEXEC | PTRACE_O_EXITKILL);
    int signal = 0;
    for (;;) {
        if (ptrace(PTRACE_SYSCALL, child, nullptr, signal) != 0) return false;
        signal = 0;
        if (waitpid(child, &status, 0) != child || !WIFSTOPPED(status)) return false;
        const int stop = WSTOPSIG(status);
        if (stop == (SIGTRAP | 0x80)) {
            __ptrace_syscall_info info{};
            ptrace(PTRACE_GET_SYSCALL_INFO, child, sizeof info, &info);
            if (info.op != PTRACE_SYSCALL_INFO_ENTRY) continue;
            const auto nr = long(info.entry.nr);
            std::uint64_t target = 0;
#ifdef SYS_rename
            if (nr == SYS_rename) target = info.entry.args[1];
#endif
            if (nr == SYS_renameat || nr == SYS_renameat2) target = info.entry.args[3];
            if (target == 0) continue;
            const std::string path = traced_string(child, target);
            if (std::filesystem::path(path).filename() == name) return true;
        } else if (stop != SIGTRAP) {
            signal = stop;  // a signal of its own: delivered (exec's stop is ours, not its)
        }
    }
}

// The first run's file set must survive a second run given the same output while it is between
// its renames (x.vtp in place, x.json not yet): the second must be refused, and leave the first
// run's set whole. The first run is traced and held at the entry of its rename onto x.json, a
// window of microseconds that a signal sent on seeing x.vtp appear almost never hits.
TEST_F(Hostile, ASecondSolveCannotWriteBetweenTheFilesOfTheFirst) {
    plates();
    const pid_t first = start_first_run(dir());
    int status = 0;
    const bool held = hold_at_rename_onto(first, "x.json", status);
    ASSERT_TRUE(held) << (WIFEXITED(status) && WEXITSTATUS(status) == 126
                              ? "this process may not trace its children (ptrace)"
                              : "the first run ended before its rename onto x.json");
    EXPECT_TRUE(std::filesystem::exists(dir() / "x.vtp"));
    EXPECT_FALSE(std::filesystem::exists(dir() / "x.json"));
    const CliRun second = run_hmcr("solve plates.json --rays 20000 -q -o x.vtp --seed 2", dir());
    ptrace(PTRACE_DETACH, first, nullptr, nullptr);
    waitpid(first, &status, 0);
    EXPECT_EQ(WEXITSTATUS(status), 0) << read_file(dir() / ".err1");
    EXPECT_EQ(second.exit_code, 2);
    EXPECT_NE(second.err.find("cannot write x."), std::string::npos) << second.err;
    EXPECT_NE(second.err.find("another hmcr run is writing it"), std::string::npos) << second.err;
    const auto [summary_seed, solution_seed] = seeds(dir());
    EXPECT_EQ(summary_seed, 1u);
    EXPECT_EQ(solution_seed, 1u);
}

}  // namespace
}  // namespace hmcr::test
