// SPDX-License-Identifier: Apache-2.0
// MPI runs give what one process gives (docs/cluster.md): `mpirun -n 1, 2, 3` of a refined
// solve, a refined-then-frozen solve (also with the control variate), a budget solve, a
// reference and a study against the same command without mpirun, file
// for file and byte for byte; summaries and tables equal but for timings and the per-process
// cache counters. And a study killed on one rank resumes with another rank count.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/support/cli_run.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

// What may differ between runs of the same solve: time, memory, the command, and what each
// process's own link cache saw.
nlohmann::json without_run_details(nlohmann::json j) {
    for (const char* key : {"timings_s", "memory", "command", "output", "link_cache"}) j.erase(key);
    for (const char* key : {"lines_cast", "oracle_evaluations", "cache_hits"})
        j["counts"].erase(key);
    for (auto& it : j["iterations"]) it.erase("seconds");
    j["options"].erase("ranks");
    j["options"].erase("threads");  // Open MPI binds each rank to a core: 1 thread each
    if (j.contains("budget")) {
        for (auto& p : j["budget"]["probes"]) p.erase("seconds");
    }
    return j;
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(read_file(p)); }

// A study table without the cells' wall times.
nlohmann::json without_seconds(nlohmann::json j) {
    if (j.is_object()) {
        j.erase("seconds");
        for (auto& [k, v] : j.items()) v = without_seconds(v);
    } else if (j.is_array()) {
        for (auto& v : j) v = without_seconds(v);
    }
    return j;
}

// Runs `command` + "one" + `suffix` alone, then `command` + "ranksK" + `suffix` under
// `mpirun -n K` for each K, and calls `check(name, K)` on each MPI run's output name.
void against_one_process(const fs::path& dir, const std::string& command, const std::string& suffix,
                         std::initializer_list<int> rank_counts,
                         const std::function<void(const std::string&, int)>& check) {
    ASSERT_EQ(run_hmcr(command + "one" + suffix, dir).exit_code, 0);
    for (int k : rank_counts) {
        const std::string name = "ranks" + std::to_string(k);
        const CliRun r = run_hmcr_mpi(k, command + name + suffix, dir);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        check(name, k);
    }
}

// The .vtp byte for byte, the summary but for run details.
void expect_same_solve(const fs::path& dir, const std::string& name, int k) {
    EXPECT_EQ(read_file(dir / (name + ".vtp")), read_file(dir / "one.vtp")) << k << " ranks";
    const auto summary = read_json(dir / (name + ".json"));
    EXPECT_EQ(summary["options"]["ranks"], k);
    EXPECT_EQ(without_run_details(summary), without_run_details(read_json(dir / "one.json")))
        << k << " ranks";
}

// `hmcr solve cornell FLAGS -q -o NAME.vtp` alone and on each of `rank_counts` ranks: the same
// solution.
void expect_same_solve_on_ranks(const std::string& flags, std::initializer_list<int> rank_counts) {
    TempDir dir;
    against_one_process(
        dir.path(), "solve cornell " + flags + " -q -o ", ".vtp", rank_counts,
        [&](const std::string& name, int k) { expect_same_solve(dir.path(), name, k); });
}

TEST(MpiRuns, RefinedSolvesAreTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks("--oracle kl --refine-share 1 --rays 300000", {1, 2, 3});
}

TEST(MpiRuns, RefineThenFreezeIsTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks("--oracle kl --refine-share 0.4 --rays 300000", {1, 2, 3});
}

// View importance (docs/design.md §3.12): its adjoint solve and weights are the same on every
// rank, so the refining pass's mesh is.
TEST(MpiRuns, ViewImportanceIsTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks("--oracle kl --refine-share 0.4 --importance views --rays 300000",
                               {1, 2, 3});
}

// The frozen pass with the control variate (docs/design.md §3.11): its zero surfaces, pilot
// and beta are the same on every rank.
TEST(MpiRuns, TheControlVariateIsTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks(
        "--oracle kl --refine-share 0.4 --control-variate constant --rays 300000", {1, 2, 3});
}

TEST(MpiRuns, TheSobolSequenceIsTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks("--oracle kl --refine-share 0.4 --sequence sobol --rays 300000",
                               {1, 2, 3});
}

// Lines used both ways (docs/design.md §3.13) in a frozen pass of cluster leaves with the control
// variate and the Sobol sequence: every back deposit, its cluster and beta on any rank count.
TEST(MpiRuns, LinesUsedBothWaysAreTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks(
        "--oracle kl --clustering isotropic --epsilon 0.3 --refine-share 0.4 --bidirectional yes "
        "--control-variate constant --sequence sobol --rays 300000",
        {1, 2, 3});
}

// Clusters as leaves (docs/design.md §2.7): at this epsilon the Cornell box's 24 patches become
// 17 leaves, 6 of them clusters; the ranks' open clusters are united like their subdivisions.
TEST(MpiRuns, ClusterLeavesAreTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks(
        "--oracle kl --clustering isotropic --epsilon 0.3 --refine-share 0.4 --rays 300000",
        {1, 2, 3});
    expect_same_solve_on_ranks(
        "--oracle power --clustering oriented --epsilon 0.3 --refine-share 0.4 --rays 300000 "
        "--bidirectional yes",
        {1, 3});
}

// A higher basis (docs/design.md §3.14): every coefficient's deposits are summed in whole quanta
// like the means', refined and frozen, both ways, with oriented clusters.
TEST(MpiRuns, HigherBasesAreTheSameBitsOnAnyRankCount) {
    expect_same_solve_on_ranks(
        "--oracle kl --clustering oriented --epsilon 0.3 --refine-share 0.4 --basis quadratic "
        "--bidirectional yes --rays 300000",
        {1, 2, 3});
}

TEST(MpiRuns, BudgetSearchesAreTheSameBitsOnTwoRanks) {
    expect_same_solve_on_ranks("--oracle power --budget 3000 --rays 300000", {2});
}

TEST(MpiRuns, ReferencesAreTheSameBitsOnAnyRankCount) {
    TempDir dir;
    against_one_process(
        dir.path(), "reference plates --max-area 0.05 --rays 40000 -q -o ", "", {1, 2, 3},
        [&](const std::string& name, int k) {
            for (const char* file : {"reference.vtp", "views/side.pfm", "views/oblique.pfm"}) {
                EXPECT_EQ(read_file(dir.path() / name / file), read_file(dir.path() / "one" / file))
                    << file << ", " << k << " ranks";
            }
        });
}

// Without a launcher's variables hmcr never starts MPI: an error is said once, with its code.
TEST(MpiRuns, AnErrorOnEveryRankIsSaidOnceWithItsExitCode) {
    TempDir dir;
    const CliRun r = run_hmcr_mpi(3, "solve cornell --rays 0 -o x.vtp", dir.path());
    EXPECT_EQ(r.exit_code, 2);
    std::size_t lines = 0;
    for (std::size_t at = 0; (at = r.err.find("hmcr: error:", at)) != std::string::npos; ++at) {
        ++lines;
    }
    EXPECT_EQ(lines, 1u) << r.err;
}

class MpiStudy : public testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = new TempDir;
        ASSERT_EQ(
            run_hmcr("reference plates --max-area 0.05 --rays 20000 -q -o ref", dir()).exit_code,
            0);
        ASSERT_EQ(run_hmcr(study("one"), dir()).exit_code, 0);
    }
    static void TearDownTestSuite() { delete s_dir; }
    static const fs::path& dir() { return s_dir->path(); }
    static std::string study(const std::string& out) {
        return "study plates --reference ref --budgets 60,120 --oracles power,kl --seeds 1 "
               "--rays 400000 -o " +
               out;
    }
    static void expect_same_study(const std::string& out) {
        EXPECT_EQ(without_seconds(read_json(dir() / out / "table.json")),
                  without_seconds(read_json(dir() / "one" / "table.json")));
        for (const auto& e : fs::directory_iterator(dir() / "one" / "meshes")) {
            const fs::path mine = dir() / out / "meshes" / e.path().filename();
            EXPECT_EQ(read_file(mine), read_file(e.path())) << mine;
        }
    }
    static TempDir* s_dir;
};
TempDir* MpiStudy::s_dir = nullptr;

// One rank computes alone; two and three hand the cells out to one and two workers.
TEST_F(MpiStudy, CellsHandedOutToRanksMakeTheSameStudy) {
    for (int k : {1, 2, 3}) {
        const std::string out = "ranks" + std::to_string(k);
        const CliRun r = run_hmcr_mpi(k, study(out), dir());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        if (k > 1) {
            const std::string last = "(rank " + std::to_string(k - 1) + ";";
            EXPECT_NE(r.err.find(last), std::string::npos) << "a rank computed no cell: " << r.err;
        }
        expect_same_study(out);
    }
}

// The process of rank `rank` whose command line mentions `marker`, or 0.
pid_t rank_process(int rank, const std::string& marker) {
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const std::string cmdline = read_file(e.path() / "cmdline");
        if (cmdline.find(HMCR_BINARY) != 0 || cmdline.find(marker) == std::string::npos) continue;
        std::string env = read_file(e.path() / "environ");
        for (char& c : env) c = c == '\0' ? '\n' : c;
        if (env.find("\nOMPI_COMM_WORLD_RANK=" + std::to_string(rank) + "\n") !=
            std::string::npos) {
            return pid_t(std::stoi(name));
        }
    }
    return 0;
}

TEST_F(MpiStudy, KilledOnOneRankItResumesWithAnotherRankCount) {
    const fs::path out = dir() / "killed";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const std::string cmd = "cd '" + dir().string() + "' && exec env " + mpirun_prefix(3) +
                                HMCR_BINARY + " " + study("killed") + " >/dev/null 2>&1";
        execl("/bin/sh", "sh", "-c", cmd.c_str(), nullptr);
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (finished_cells(out) == 0 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    const pid_t victim = rank_process(1, "killed");
    ASSERT_GT(victim, 0);
    kill(victim, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the run did not notice";
    const std::size_t before = finished_cells(out);
    ASSERT_GE(before, 1u);
    ASSERT_LT(before, 4u) << "the study finished before it could be killed";
    EXPECT_FALSE(fs::exists(out / "table.md"));

    const CliRun r = run_hmcr_mpi(2, study("killed"), dir());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::size_t skipped = 0;
    for (std::size_t at = 0; (at = r.err.find("done before, skipped", at)) != std::string::npos;
         ++at) {
        ++skipped;
    }
    EXPECT_EQ(skipped, before);
    expect_same_study("killed");
}

}  // namespace
}  // namespace hmcr::test
