// SPDX-License-Identifier: Apache-2.0
// The command line as a user meets it: bad input gets one line on stderr, exit code 2 and
// no output file; a good run writes the .vtp and its JSON summary.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "meshes/scene.h"
#include "rays/patch.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

class Cli : public testing::Test {
protected:
    CliRun hmcr(const std::string& args) const { return run_hmcr(args, m_dir); }
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
                         "oracle must be one of power, ks, mi, kl, cs, hl, vt, got 'nope'");
}

TEST_F(Cli, BadNumberIsRejected) {
    expect_clean_failure(hmcr("solve plates --rays lots -o " + (m_dir / "out.vtp").string()),
                         "--rays");
    expect_clean_failure(hmcr("solve plates --epsilon -3 -o " + (m_dir / "out.vtp").string()),
                         "epsilon");
    expect_clean_failure(hmcr("solve plates --rays 1.5e0 -o " + (m_dir / "out.vtp").string()),
                         "--rays: '1.5e0' is not a whole number");
    expect_clean_failure(hmcr("solve plates --rays 1e400 -o " + (m_dir / "out.vtp").string()),
                         "--rays: '1e400' is not a whole number");
    // Beyond 64 bits: refused, not saturated (which would ask for 1.8e19 rays).
    expect_clean_failure(
        hmcr("solve plates --rays 99999999999999999999 -o " + (m_dir / "out.vtp").string()),
        "--rays: '99999999999999999999' is not a whole number");
    expect_clean_failure(
        hmcr("solve plates --seed 99999999999999999999 -o " + (m_dir / "out.vtp").string()),
        "--seed: '99999999999999999999' is not a whole number");
    const CliRun budgets = hmcr("study plates --reference " + (m_dir / "none").string() +
                                " --budgets 2e1,1.5 -o " + (m_dir / "s").string());
    EXPECT_EQ(budgets.exit_code, 2);
    EXPECT_NE(budgets.err.find("budgets: '1.5' is not a positive leaf count"), std::string::npos)
        << budgets.err;
}

// Counts may be written in scientific notation when they are whole numbers.
TEST_F(Cli, CountsTakeScientificNotation) {
    const CliRun r = hmcr("solve plates --rays 2.5e4 --quiet -o " + (m_dir / "e.vtp").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(m_dir / "e.json");
    EXPECT_EQ(nlohmann::json::parse(in)["options"]["rays"], 25'000);
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

// `info` on a solution names what it measures: the file's cells, which are its leaves but in a
// clustered solution, where a cluster is one leaf of several cells.
TEST_F(Cli, InfoOnASolutionSaysWhatItMeasures) {
    ASSERT_EQ(hmcr("solve cornell --clustering isotropic --budget 20 --budget-tolerance 0.3 "
                   "--rays 1e5 -q -o c.vtp")
                  .exit_code,
              0);
    const auto counts = nlohmann::json::parse(read_file(m_dir / "c.json"))["counts"];
    ASSERT_GT(counts["cluster_leaves"].get<int>(), 0);  // a clustered solution
    const CliRun info = hmcr("info c.vtp --lines 1e4 --json");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const auto j = nlohmann::json::parse(info.out);
    EXPECT_EQ(j["states"], "cells");
    EXPECT_EQ(j["leaves"], counts["leaves"]);
    EXPECT_EQ(j["clusters"], counts["cluster_leaves"]);
    EXPECT_GT(j["patches"].get<int>(), counts["leaves"].get<int>());  // the cells
    EXPECT_EQ(j["scene"], "cornell (cells of c.vtp, not its " + counts["leaves"].dump() +
                              " leaves: " + counts["cluster_leaves"].dump() +
                              " of them clusters, whose cells are measured each apart)");
    const CliRun table = hmcr("info c.vtp --lines 1e4");
    EXPECT_NE(table.out.find("): " + j["patches"].dump() + " cells,"), std::string::npos)
        << table.out;
    ASSERT_EQ(hmcr("solve plates --rays 1e4 -q -o p.vtp").exit_code, 0);
    const auto plain = nlohmann::json::parse(hmcr("info p.vtp --lines 1e4 --json").out);
    EXPECT_EQ(plain["states"], "leaves");
    EXPECT_EQ(plain["scene"], "plates (leaves of p.vtp)");
    EXPECT_FALSE(plain.contains("clusters"));
}

// A sweep script that holds much memory starts each solve with posix_spawn, as Python's
// subprocess does. The solve's summary must give its own peak, not the script's.
TEST_F(Cli, PeakMemoryIsTheSolvesOwnNotItsParents) {
    const std::string vtp = (m_dir / "p.vtp").string();
    auto spawned_solve_peak = [&] {
        std::vector<std::string> args = {HMCR_BINARY, "solve", "plates", "--rays",
                                         "20000",     "-q",    "-o",     vtp};
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        pid_t pid = 0;
        EXPECT_EQ(posix_spawn(&pid, HMCR_BINARY, nullptr, nullptr, argv.data(), environ), 0);
        int status = 0;
        EXPECT_EQ(waitpid(pid, &status, 0), pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        return nlohmann::json::parse(read_file(m_dir / "p.json"))["memory"]["peak_bytes"]
            .get<double>();
    };
    const double alone = spawned_solve_peak();
    std::vector<char> held(std::size_t(512) << 20, 1);  // now resident in this process
    const double beside = spawned_solve_peak();
    EXPECT_GT(alone, 0);
    // The same solve, so about the same peak; counting the parent would add about 512 MB.
    EXPECT_LT(beside, alone + double(held.size()) / 2) << "the parent's memory was counted";
    EXPECT_EQ(held[held.size() / 3], 1);  // still held while the solve ran
}

TEST_F(Cli, SolveWritesTheMeshAndASummaryWithCountsAndTimings) {
    const fs::path vtp = m_dir / "sub" / "plates.vtp";
    const CliRun r = hmcr("solve plates --rays 20000 --seed 4 --threads 2 -o " + vtp.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(vtp));
    const auto summary = nlohmann::json::parse(read_file(m_dir / "sub" / "plates.json"));
    EXPECT_EQ(summary["options"]["seed"], 4);
    EXPECT_EQ(summary["options"]["threads"], 2);
    // The scene's totals are those of its patches (the tree is gone when the summary is written).
    const PatchSet set = build_patch_set(load_scene("plates").mesh);
    EXPECT_EQ(summary["scene"]["patches"], set.patches.size());
    EXPECT_EQ(summary["scene"]["total_area_m2"].get<double>(), set.total_area);
    EXPECT_EQ(summary["scene"]["max_emitted_power_w"].get<double>(), set.max_emitted_power);
    EXPECT_NEAR(summary["counts"]["rays"].get<double>(), 20000, 400);
    EXPECT_GT(summary["counts"]["leaves"].get<int>(), 1);
    EXPECT_GE(summary["timings_s"]["total"].get<double>(),
              summary["timings_s"]["solve"].get<double>());
    EXPECT_GT(summary["memory"]["peak_bytes"].get<double>(), 0);
    // Without a terminal, progress is a line every 10%.
    EXPECT_NE(r.err.find("shooting rays: 100%"), std::string::npos) << r.err;
    for (const auto& e : fs::directory_iterator(m_dir / "sub")) {
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
    }
}

// An MGF file solves like an OBJ: a one-sided lamp over a floor, with a non-diffuse statement
// told once; --mgf-segments sets the tessellation of its sphere.
TEST_F(Cli, SolveReadsAnMgfFile) {
    std::ofstream(m_dir / "lamp.mgf") << "m floor =\n sides 1\n rd 0.5\n ts 0.1 0\n"
                                         "v a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 1 1 0\n"
                                         "v d =\n p 0 1 0\nf a b c d\n"
                                         "m bulb =\n sides 1\n ed 100\nv o =\n p 0.5 0.5 1\n"
                                         "sph o 0.1\n";
    const CliRun r = hmcr("solve " + (m_dir / "lamp.mgf").string() +
                          " --mgf-segments 8 --rays 20000 -q -o " + (m_dir / "lamp.vtp").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto summary = nlohmann::json::parse(read_file(m_dir / "lamp.json"));
    EXPECT_EQ(summary["scene"]["patches"], 1 + 8 * 4);
    // ed times the tessellated sphere's area, below the true one by at most (pi / 8)^2.
    const double sphere = 4 * M_PI * 0.01, emitted = summary["power"]["emitted_w"][0];
    EXPECT_LT(emitted, 100 * sphere);
    EXPECT_GT(emitted, 100 * sphere * (1 - (M_PI / 8) * (M_PI / 8)));
    const CliRun loud = hmcr("solve " + (m_dir / "lamp.mgf").string() + " --rays 20000 -o " +
                             (m_dir / "lamp.vtp").string());
    EXPECT_NE(loud.err.find("ignored (hmcr reads reflection rd and rs and emission ed): ts 1 time"),
              std::string::npos)
        << loud.err;
}

TEST_F(Cli, RenderAndReferenceWriteTheirFiles) {
    const std::string vtp = (m_dir / "p.vtp").string();
    ASSERT_EQ(hmcr("solve plates --rays 20000 --quiet -o " + vtp).exit_code, 0);
    const CliRun r = hmcr("render " + vtp + " --scene plates --view side --samples 2 -o " +
                          (m_dir / "p.png").string() + " --pfm " + (m_dir / "p.pfm").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(m_dir / "p.png"));
    EXPECT_TRUE(fs::exists(m_dir / "p.pfm"));
    const CliRun ref =
        hmcr("reference plates --max-area 0.05 --rays 20000 -q -o " + (m_dir / "ref").string());
    EXPECT_EQ(ref.exit_code, 0) << ref.err;
    for (const char* f : {"reference.vtp", "reference.json", "views/side.pfm", "views/side.png"}) {
        EXPECT_TRUE(fs::exists(m_dir / "ref" / f)) << f;
    }
    const auto summary = nlohmann::json::parse(read_file(m_dir / "ref" / "reference.json"));
    EXPECT_GT(summary["reference"]["views"]["side"]["exposure"].get<double>(), 0);
    EXPECT_TRUE(summary["reference"]["convergence"].contains("object_space_relative_l2"));
}

TEST_F(Cli, RenderRejectsAnUnknownViewAndAMissingSolution) {
    const std::string vtp = (m_dir / "p.vtp").string();
    ASSERT_EQ(hmcr("solve plates --rays 5000 --quiet -o " + vtp).exit_code, 0);
    const CliRun view = hmcr("render " + vtp + " --scene plates --view nope -o " +
                             (m_dir / "out.vtp.png").string());
    EXPECT_EQ(view.exit_code, 2);
    EXPECT_NE(view.err.find("no view 'nope' (views: side"), std::string::npos) << view.err;
    const CliRun missing = hmcr("render " + (m_dir / "none.vtp").string() + " --scene plates -o " +
                                (m_dir / "x.png").string());
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("none.vtp: no such file"), std::string::npos) << missing.err;
    EXPECT_FALSE(fs::exists(m_dir / "x.png"));
}

// A broken reference.json is named as such (not as a scene's settings), with exit code 2.
TEST_F(Cli, RenderNamesABrokenReferenceFile) {
    const std::string vtp = (m_dir / "p.vtp").string();
    ASSERT_EQ(hmcr("solve plates --rays 5000 --quiet -o " + vtp).exit_code, 0);
    fs::create_directories(m_dir / "ref");
    for (const char* text :
         {"{}", "{\"reference\": {\"views\": {\"side\": {\"exposure\": \"x\"}}}}", "{not json"}) {
        std::ofstream(m_dir / "ref" / "reference.json") << text;
        const CliRun r = hmcr("render " + vtp + " --scene plates --reference " +
                              (m_dir / "ref").string() + " -o " + (m_dir / "x.png").string());
        EXPECT_EQ(r.exit_code, 2) << text;
        EXPECT_NE(r.err.find("ref/reference.json:"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("solver"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(m_dir / "x.png"));
    }
}

TEST_F(Cli, InfoPrintsTheMeasuresAndWarnsOnAnOpenScene) {
    const CliRun closed = hmcr("info furnace --lines 200000");
    EXPECT_EQ(closed.exit_code, 0) << closed.err;
    EXPECT_NE(closed.out.find("I_S   mutual information"), std::string::npos) << closed.out;
    EXPECT_EQ(closed.err, "");
    const CliRun open = hmcr("info plates --lines 200000 --json");
    EXPECT_EQ(open.exit_code, 0) << open.err;
    const auto j = nlohmann::json::parse(open.out);
    EXPECT_GT(j["open_fraction"].get<double>(), 0.5);
    EXPECT_TRUE(j["i_s"].contains("standard_error"));
    EXPECT_NE(open.err.find("warning"), std::string::npos) << open.err;  // JSON warns too
    EXPECT_EQ(hmcr("info furnace --lines 3").exit_code, 2);
}

TEST_F(Cli, InfoWithGlobalLines) {
    const CliRun r = hmcr("info furnace --method global --lines 100000 --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "global");
    EXPECT_EQ(j["lines"].get<std::size_t>(), 100'000u);
    EXPECT_GT(j["samples"].get<std::size_t>(), 100'000u);  // a line through the box gives two
    const CliRun bad = hmcr("info furnace --method globl");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("unknown line method 'globl'"), std::string::npos) << bad.err;
    EXPECT_EQ(bad.out, "");
}

// A scene's solver setting of the wrong type is named with its file and key.
TEST_F(Cli, SceneSolverSettingOfTheWrongTypeIsNamed) {
    fs::copy(fs::path(HMCR_SCENE_DIR) / "plates", m_dir / "plates");
    const fs::path json = m_dir / "plates" / "plates.json";
    auto j = nlohmann::json::parse(read_file(json));
    j["solver"] = {{"rays", "many"}};
    std::ofstream(json) << j.dump();
    expect_clean_failure(hmcr("solve " + json.string() + " -o " + (m_dir / "out.vtp").string()),
                         "plates.json: solver.rays: must be a whole number in range, got 'many'");
}

// A scene file's bad setting is an error even when the command line overrides it: the file is
// wrong whatever is given with it.
TEST_F(Cli, BadSceneSettingIsRefusedEvenWhenOverridden) {
    fs::copy(fs::path(HMCR_SCENE_DIR) / "plates", m_dir / "plates");
    const fs::path json = m_dir / "plates" / "plates.json";
    auto j = nlohmann::json::parse(read_file(json));
    j["solver"] = {{"rays", -5}};
    std::ofstream(json) << j.dump();
    const std::string out = " -o " + (m_dir / "out.vtp").string();
    expect_clean_failure(hmcr("solve " + json.string() + out), "plates.json: solver.rays: ");
    expect_clean_failure(hmcr("solve " + json.string() + " --rays 1000" + out),
                         "plates.json: solver.rays: ");
}

// A bare OBJ, without materials or light: its geometry can be measured, but it cannot be
// solved.
TEST_F(Cli, InfoNeedsNoEmitterButSolveDoes) {
    std::ofstream(m_dir / "dark.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                         "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                         "f 1 2 3 4\nf 5 8 7 6\n";
    const std::string obj = (m_dir / "dark.obj").string();
    const CliRun info = hmcr("info " + obj + " --lines 1000 --json");
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out)["patches"], 2);
    expect_clean_failure(hmcr("solve " + obj + " -o " + (m_dir / "out.vtp").string()),
                         "dark.obj:9: face has no material");
}

// The link weight is a solver setting: in the summary's options and the .vtp's field data.
TEST_F(Cli, LinkWeightIsRecordedInTheOutputs) {
    const std::string vtp = (m_dir / "p.vtp").string();
    ASSERT_EQ(hmcr("solve plates --rays 5000 --link-weight total -q -o " + vtp).exit_code, 0);
    const auto summary = nlohmann::json::parse(read_file(m_dir / "p.json"));
    EXPECT_EQ(summary["options"]["link_weight"], "total");
    const std::string bytes = read_file(vtp);
    EXPECT_NE(bytes.find("Name=\"LinkWeight\""), std::string::npos);
    expect_clean_failure(hmcr("solve plates --link-weight most -o " + (m_dir / "out.vtp").string()),
                         "link-weight");
}

// A reference stops at --stop, else at its scene's solver.stop, else at 1e-4 (not the solver's
// 0.01), and reports what stopping left out.
TEST_F(Cli, ReferenceStopComesFromTheFlagTheSceneOrItsDefault) {
    fs::copy(fs::path(HMCR_SCENE_DIR) / "plates", m_dir / "plates");
    const fs::path json = m_dir / "plates" / "plates.json";
    auto j = nlohmann::json::parse(read_file(json));
    j["solver"] = {{"stop", 0.2}};
    std::ofstream(json) << j.dump();
    auto stop_of = [&](const std::string& scene, const std::string& flags, const char* dir) {
        const CliRun r = hmcr("reference " + scene + " --max-area 0.05 --rays 20000 -q " + flags +
                              " -o " + (m_dir / dir).string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const auto ref = nlohmann::json::parse(read_file(m_dir / dir / "reference.json"));
        EXPECT_EQ(ref["reference"]["truncation"]["relative_bias"].size(), 3u);
        return ref["reference"]["truncation"]["stop"].get<double>();
    };
    EXPECT_EQ(stop_of("plates", "", "a"), 1e-4);
    EXPECT_EQ(stop_of("plates", "--stop 0.05", "b"), 0.05);
    EXPECT_EQ(stop_of(json.string(), "", "c"), 0.2);
    EXPECT_EQ(stop_of(json.string(), "--stop 0.05", "d"), 0.05);
}

TEST_F(Cli, QuietPrintsNothing) {
    const CliRun r = hmcr("solve plates --rays 5000 --quiet -o " + (m_dir / "q.vtp").string());
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out + r.err, "");
}

}  // namespace
}  // namespace hmcr::test
