// The command line as a user meets it: bad input gets one line on stderr, exit code 2 and
// no output file; a good run writes the .vtp and its JSON summary.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

struct CliRun {
    int exit_code = -1;
    std::string out, err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class Cli : public testing::Test {
protected:
    CliRun hmcr(const std::string& args) const {
        const std::string cmd = std::string(HMCR_BINARY) + " " + args + " >" +
                                (m_dir / "stdout").string() + " 2>" + (m_dir / "stderr").string();
        const int status = std::system(cmd.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(m_dir / "stdout"),
                slurp(m_dir / "stderr")};
    }
    void expect_clean_failure(const CliRun& r, const std::string& needle) const {
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(m_dir / "out.vtp"));
        EXPECT_FALSE(fs::exists(m_dir / "out.json"));
    }
    TempDir m_temp;
    const fs::path& m_dir = m_temp.path();
};

TEST_F(Cli, UnknownOracleListsTheValidOnes) {
    expect_clean_failure(hmcr("solve plates --oracle nope -o " + (m_dir / "out.vtp").string()),
                         "unknown oracle 'nope' (valid: power");
}

TEST_F(Cli, BadNumberIsRejected) {
    expect_clean_failure(hmcr("solve plates --rays lots -o " + (m_dir / "out.vtp").string()),
                         "--rays");
    expect_clean_failure(hmcr("solve plates --epsilon -3 -o " + (m_dir / "out.vtp").string()),
                         "epsilon");
}

TEST_F(Cli, MalformedSceneNamesFileAndLine) {
    const fs::path obj = m_temp.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    expect_clean_failure(hmcr("solve " + obj.string() + " -o " + (m_dir / "out.vtp").string()),
                         "bad.obj:4");
}

TEST_F(Cli, UnknownSceneNameListsTheBundledOnes) {
    expect_clean_failure(hmcr("solve nowhere -o " + (m_dir / "out.vtp").string()), "cornell");
}

TEST_F(Cli, OraclesAndScenesAreListed) {
    const CliRun o = hmcr("oracles");
    EXPECT_EQ(o.exit_code, 0);
    EXPECT_NE(o.out.find("power"), std::string::npos);
    const CliRun s = hmcr("scenes");
    EXPECT_NE(s.out.find("cube-room"), std::string::npos);
}

TEST_F(Cli, SolveWritesTheMeshAndASummaryWithCountsAndTimings) {
    const fs::path vtp = m_dir / "sub" / "plates.vtp";
    const CliRun r = hmcr("solve plates --rays 20000 --seed 4 --threads 2 -o " + vtp.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(vtp));
    const auto summary = nlohmann::json::parse(slurp(m_dir / "sub" / "plates.json"));
    EXPECT_EQ(summary["options"]["seed"], 4);
    EXPECT_EQ(summary["options"]["threads"], 2);
    EXPECT_NEAR(summary["counts"]["rays"].get<double>(), 20000, 400);
    EXPECT_GT(summary["counts"]["leaves"].get<int>(), 1);
    EXPECT_GE(summary["timings_s"]["total"].get<double>(), summary["timings_s"]["solve"].get<double>());
    EXPECT_GT(summary["memory"]["peak_bytes"].get<double>(), 0);
    // Without a terminal, progress is a line every 10%.
    EXPECT_NE(r.err.find("100% of the rays shot"), std::string::npos) << r.err;
    for (const auto& e : fs::directory_iterator(m_dir / "sub")) {
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
    }
}

TEST_F(Cli, QuietPrintsNothing) {
    const CliRun r = hmcr("solve plates --rays 5000 --quiet -o " + (m_dir / "q.vtp").string());
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out + r.err, "");
}

}  // namespace
}  // namespace hmcr::test
