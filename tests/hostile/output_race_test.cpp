// Two runs given the same output at once (a script started twice, two jobs of one array): the
// second is refused while the first holds the output (common/output_lock.h), so the files left
// are always one run's set, never x.vtp of one beside x.json of the other.
#include <poll.h>
#include <sys/inotify.h>

#include <nlohmann/json.hpp>

#include "tests/hostile/hostile.h"
#include "viz/solution_file.h"

namespace hmcr::test {
namespace {

// The seed of x.json and of x.vtp in `dir`: equal when both are one run's.
std::pair<std::uint64_t, std::uint64_t> seeds(const std::filesystem::path& dir) {
    const auto summary = nlohmann::json::parse(read_file(dir / "x.json"));
    return {summary["options"]["seed"].get<std::uint64_t>(), read_solution(dir / "x.vtp").meta.seed};
}

// Waits (up to 30 s) until a file named `name` is renamed into the folder `watch` watches.
bool renamed_in(int watch, const std::string& name) {
    alignas(inotify_event) char buffer[4096];
    pollfd p{watch, POLLIN, 0};
    while (::poll(&p, 1, 30000) == 1) {
        const ssize_t n = ::read(watch, buffer, sizeof buffer);
        for (ssize_t at = 0; at < n;) {
            const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
            if ((e->mask & IN_MOVED_TO) && e->len > 0 && name == e->name) return true;
            at += ssize_t(sizeof(inotify_event) + e->len);
        }
    }
    return false;
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
            EXPECT_TRUE(text.empty() || text.find("another hmcr run is writing it") != std::string::npos)
                << text;
            refusals += !text.empty();
        }
        const auto [summary_seed, solution_seed] = seeds(dir());
        ASSERT_EQ(summary_seed, solution_seed) << "round " << round << ": a mixed set";
    }
    std::cout << refusals << " of 24 runs refused\n";
}

// The first run is stopped the moment its x.vtp is in place, before x.json (where the second would
// replace it all); the second runs then: it must be refused, and leave the first run's set whole.
TEST_F(Hostile, ASecondSolveCannotWriteBetweenTheFilesOfTheFirst) {
    plates();
    const int watch = inotify_init1(IN_CLOEXEC);
    ASSERT_GE(watch, 0);
    ASSERT_GE(inotify_add_watch(watch, dir().c_str(), IN_MOVED_TO), 0);
    const pid_t first = fork();
    if (first == 0) {
        const std::string cmd = "cd '" + dir().string() + "' && exec " + HMCR_BINARY +
                                " solve plates.json --rays 20000 --epsilon 1e-6 -q -o x.vtp "
                                "--seed 1 2>.err1";
        execl("/bin/sh", "sh", "-c", cmd.c_str(), nullptr);
        _exit(127);
    }
    const bool caught = renamed_in(watch, "x.vtp");
    kill(first, SIGSTOP);
    ::close(watch);
    const CliRun second = run_hmcr("solve plates.json --rays 20000 -q -o x.vtp --seed 2", dir());
    kill(first, SIGCONT);
    int status = 0;
    waitpid(first, &status, 0);
    ASSERT_TRUE(caught);
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
