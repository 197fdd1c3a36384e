// SPDX-License-Identifier: Apache-2.0
// Hostile study folders: a cell file cut short, emptied or holding values no study makes is
// computed again, not fatal and not tabled; a folder made with other settings is refused, not
// mixed into one table; a study's size and seeds are bounded before anything is written;
// `hmcr plot` refuses a folder that holds no study's table, and a machine without matplotlib;
// a study whose plotting script fails is still whole.
#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/version.h"
#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

class HostileStudy : public Hostile {
protected:
    // These studies are about their cells: their plots, which take a second each to draw, are
    // left out (a Python without matplotlib, so a warning) unless a test names its own Python.
    // Plots drawn are tested in tests/app/trace_cli_test.cpp and write_confinement_test.cpp.
    void SetUp() override {
        const char* python = std::getenv("HMCR_PYTHON");
        if (python != nullptr) m_python = python;
        setenv("HMCR_PYTHON", "/bin/false", 1);
        plates(kPlatesObj, kPlatesMtl,
               R"({"mesh": "plates.obj", "solver": {"rays": 20000}, "views": [{"name": "side",
                   "position": [2.8, 0.5, 0.5], "look_at": [0.5, 0.5, 0.5], "width": 32,
                   "height": 32}]})");
        accepted("reference plates.json --max-area 0.1 --rays 20000 -q -o ref");  // rays its own
    }
    void TearDown() override {
        if (m_python) {
            setenv("HMCR_PYTHON", m_python->c_str(), 1);
        } else {
            unsetenv("HMCR_PYTHON");
        }
    }
    std::optional<std::string> m_python;
    static constexpr const char* kStudy =
        "study plates.json --reference ref --budgets 20 --oracles power --seeds 2 -o st";
    std::filesystem::path cell(int seed) const {
        return dir() / "st" / "cells" / ("plates-power-B20-s" + std::to_string(seed) + ".json");
    }
};

TEST_F(HostileStudy, BrokenCellFilesAreComputedAgain) {
    accepted(kStudy);
    const std::string good = read_file(cell(1));
    const std::string table = read_file(dir() / "st" / "table.csv");
    // A number beyond double's range was an uncaught out_of_range (found by the cell fuzzer).
    for (const std::string& broken : {std::string("{}"), good.substr(0, good.size() / 2),
                                      std::string(), std::string("{\"seed\": 1e400}")}) {
        m_temp.write("st/cells/plates-power-B20-s1.json", broken);
        const CliRun r = accepted(kStudy);
        EXPECT_NE(r.err.find("plates-power-B20-s1: unreadable"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("computing it again"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("plates-power-B20-s2: done before, skipped"), std::string::npos);
        EXPECT_EQ(nlohmann::json::parse(read_file(cell(1)))["seed"], 1);
    }
}

// Values no study writes: each would go into the tables as a result (a negative error in bold
// as the best, -3 leaves printed as 2^64 - 3).
TEST_F(HostileStudy, CellsWhoseValuesDoNotCheckOutAreComputedAgain) {
    accepted(kStudy);
    const nlohmann::json good = nlohmann::json::parse(read_file(cell(1)));
    // Every field's check is in tests/studies/cell_files_test.cpp.
    const std::vector<std::pair<std::string, nlohmann::json>> spoiled = {
        {"/leaves", -3},
        {"/object_error/relative_l2", -0.5},
        {"/views/side/rmse_p", -1.0},
    };
    for (const auto& [pointer, value] : spoiled) {
        nlohmann::json bad = good;
        bad[nlohmann::json::json_pointer(pointer)] = value;
        m_temp.write("st/cells/plates-power-B20-s1.json", bad.dump(2));
        const CliRun r = accepted(kStudy);
        EXPECT_NE(r.err.find("plates-power-B20-s1: unreadable"), std::string::npos)
            << pointer << "\n"
            << r.err;
        EXPECT_NE(r.err.find(pointer.substr(pointer.rfind('/') + 1)), std::string::npos) << r.err;
        EXPECT_EQ(nlohmann::json::parse(read_file(cell(1)))["leaves"], good["leaves"]) << pointer;
    }
}

// A cell of the study's settings that lacks what the study needs of it (a view's result, the
// mesh error, the rays of its budget) is computed again, not tabled short of a seed.
TEST_F(HostileStudy, CellsThatLackWhatTheStudyNeedsAreComputedAgain) {
    const std::string study = std::string(kStudy) + " --budget-tolerance 0.1 --mesh-rays 20000";
    accepted(study);
    const nlohmann::json good = nlohmann::json::parse(read_file(cell(1)));
    ASSERT_EQ(good["status"], "ok");
    const std::vector<std::tuple<std::string, nlohmann::json, std::string>> spoiled = {
        {"/views", nlohmann::json::object(), "no result for view 'side'"},
        {"/mesh_views", nlohmann::json::object(), "no mesh error for view 'side'"},
        {"/rays", 5, "rays 5, not the 20000 of this cell"},
        {"/mesh_rays", 0, "mesh_rays 0, not the 20000 of this cell"},
    };
    for (const auto& [pointer, value, note] : spoiled) {
        nlohmann::json bad = good;
        bad[nlohmann::json::json_pointer(pointer)] = value;
        m_temp.write("st/cells/plates-power-B20-s1.json", bad.dump(2));
        const CliRun r = accepted(study);
        EXPECT_NE(
            r.err.find("plates-power-B20-s1: the file holds " + note + "; computing it again"),
            std::string::npos)
            << pointer << "\n"
            << r.err;
        EXPECT_EQ(nlohmann::json::parse(read_file(cell(1)))["views"], good["views"]) << pointer;
        EXPECT_NE(read_file(dir() / "st" / "table.md").find("| power | 2/2 |"), std::string::npos)
            << pointer;
    }
    const std::string sampling =
        "study plates.json --reference ref --samplers uniform --spp 2 --seeds 1 -o sst";
    accepted(sampling);
    const std::filesystem::path file = dir() / "sst" / "cells" / "plates-uniform-spp2-s1.json";
    nlohmann::json bad = nlohmann::json::parse(read_file(file));
    bad["views"] = nlohmann::json::object();
    m_temp.write("sst/cells/plates-uniform-spp2-s1.json", bad.dump(2));
    const CliRun r = accepted(sampling);
    EXPECT_NE(r.err.find("the file holds no result for view 'side'; computing it again"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(nlohmann::json::parse(read_file(file))["views"].size(), 1u);
}

TEST_F(HostileStudy, TheCellCountAndTheSeedsAreBounded) {
    refused("study plates.json --reference ref --budgets 20 --oracles all --seeds 2000 -o big",
            "7 x 2000 seeds = 14000 cells");
    refused("study plates.json --reference ref --samplers uniform --seeds 10001 -o big",
            "1 x 10001 seeds = 10001 cells, more than the 10000 a study may have");
    refused(
        "study plates.json --reference ref --budgets 20 --oracles power "
        "--first-seed 18446744073709551614 --seeds 3 -o big",
        "pass the largest seed");
    refused(
        "study plates.json --reference ref --samplers uniform "
        "--first-seed 18446744073709551615 --seeds 2 -o big",
        "pass the largest seed");
}

// A cells/ folder that takes no file is found before the first cell is computed: the one line
// of the refusal is all the study prints (no budget probe before it).
TEST_F(HostileStudy, ACellsFolderThatTakesNoFileIsFoundBeforeAnyCell) {
    m_temp.write("st/cells", "a file where the folder goes");
    refused(kStudy, "cannot write st/cells/plates-power-B20-s1.json: not a folder: st/cells");
    std::filesystem::remove(dir() / "st" / "cells");
    std::filesystem::create_directories(dir() / "st" / "cells");
    const Unwritable read_only(dir() / "st" / "cells");
    if (!read_only.ok()) GTEST_SKIP() << "no read-only folder can be made here";
    refused(kStudy, "cannot write st/cells/plates-power-B20-s1.json");
    refused("study plates.json --reference ref --samplers uniform --spp 2 --seeds 1 -o st",
            "cannot write st/cells/plates-uniform-spp2-s1.json");
}

// A signal during a cell's frozen re-solve, after its own mesh and images are made: none of the
// cell's files is left, as the study says ("no partial output left").
TEST_F(HostileStudy, ACellInterruptedInItsReSolveLeavesNoneOfItsFiles) {
    HmcrChild child(
        "study plates.json --reference ref --budgets 20 --oracles power --seeds 1 "
        "--budget-tolerance 0.1 --mesh-rays 1e12 -o st",
        dir(), 60);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (read_file(dir() / ".stderr").find("mesh error: the mesh frozen") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // well into the re-solve
    child.signal(SIGTERM);
    const ChildExit e = child.wait();
    EXPECT_EQ(e.code, 128 + SIGTERM) << e.err;
    EXPECT_NE(e.err.find("mesh error: the mesh frozen"), std::string::npos) << e.err;
    EXPECT_NE(e.err.find("no partial output left"), std::string::npos) << e.err;
    std::vector<std::string> left;  // the folder goes too, made by this run
    std::error_code none;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir() / "st", none))
        left.push_back(entry.path().lexically_relative(dir()).string());
    EXPECT_TRUE(left.empty()) << left.front();
}

TEST_F(HostileStudy, QuietMeansQuiet) {
    accepted(kStudy + std::string(" -q"));
    m_temp.write("st/cells/plates-power-B20-s1.json", "{}");
    const CliRun r = accepted(kStudy + std::string(" -q"));
    EXPECT_EQ(r.out + r.err, "");
    const CliRun sampling = accepted(
        "study plates.json --reference ref --samplers uniform --spp 2 --seeds 1 -q -o sst");
    EXPECT_EQ(sampling.out + sampling.err, "");
}

TEST_F(HostileStudy, OtherSettingsAreRefusedUnlessRedone) {
    accepted(kStudy);
    const CliRun r = refused(std::string(kStudy) + " --lines 4", "made with other settings");
    EXPECT_NE(r.err.find("lines"), std::string::npos) << r.err;
    refused(std::string(kStudy) + " --rays 30000", "solve/rays is 30000 now");
    const CliRun redo = accepted(std::string(kStudy) + " --lines 4 --redo");
    EXPECT_NE(redo.err.find("made with other settings; computing it again"), std::string::npos);
    EXPECT_EQ(nlohmann::json::parse(read_file(cell(2)))["settings"]["solve"]["lines"], 4);
    // Threads and cache size change no result, so they are not settings of a study.
    accepted(std::string(kStudy) + " --lines 4 --threads 1 --cache-mb 1");
}

// A cell of a version whose bits differ (another major or minor number) is another cell.
TEST_F(HostileStudy, CellsOfAVersionWithOtherBitsAreRefusedUnlessRedone) {
    accepted(kStudy);
    nlohmann::json c = nlohmann::json::parse(read_file(cell(2)));
    ASSERT_EQ(c["settings"]["bits_version"], std::string(bits_version()));
    c["settings"]["bits_version"] = "0.1";
    m_temp.write("st/cells/plates-power-B20-s2.json", c.dump());
    refused(kStudy, "bits_version is \"" + std::string(bits_version()) + "\" now");
    accepted(std::string(kStudy) + " --redo");
}

TEST_F(HostileStudy, PlotRefusesWhatIsNoStudysTable) {
    accepted(kStudy);
    m_temp.write("empty/readme.txt", "no table here");
    refused("plot nowhere", "nowhere/table.json: no such file");
    refused("plot empty", "empty/table.json: no such file");
    const std::string table = read_file(dir() / "st" / "table.json");
    m_temp.write("st/table.json", table.substr(0, table.size() / 2));
    refused("plot st", "st/table.json:");
    nlohmann::json j = nlohmann::json::parse(table);
    j["cells"][0]["oracle"] = "nope";
    m_temp.write("st/table.json", j.dump());
    refused("plot st", "st/table.json: unknown oracle 'nope'");
    j["cells"][0]["leaves"] = "many";
    m_temp.write("st/table.json", j.dump());
    refused("plot st", "st/table.json: ");
    m_temp.write("st/table.json", R"({"scene": "x", "options": {}, "cells": []})");
    refused("plot st", "neither a meshing study's table");
}

// Without matplotlib a study completes, its tables written and one line saying how to draw its
// plots; `hmcr plot` then refuses, writing nothing.
TEST_F(HostileStudy, NoMatplotlibLeavesTheStudyWhole) {
    const std::string no_python = "env HMCR_PYTHON=/nonexistent/python3 ";
    const CliRun study = run_launched(no_python, kStudy, dir(), 60);
    EXPECT_EQ(study.exit_code, 0) << study.err;
    EXPECT_TRUE(std::filesystem::exists(dir() / "st" / "table.tex"));
    EXPECT_TRUE(std::filesystem::exists(dir() / "st" / "plots" / "plot_data.json"));
    EXPECT_FALSE(std::filesystem::exists(dir() / "st" / "plots" / "error_vs_elements.pdf"));
    EXPECT_NE(study.err.find("hmcr: warning: plots not drawn: no Python with matplotlib "
                             "($HMCR_PYTHON (/nonexistent/python3)): install it (Debian: "
                             "python3-matplotlib), then `hmcr plot st`\n"),
              std::string::npos)
        << study.err;
    const auto before = snapshot(dir());
    const CliRun plot = run_launched(no_python, "plot st", dir(), 60);
    EXPECT_EQ(plot.exit_code, 2);
    EXPECT_EQ(std::count(plot.err.begin(), plot.err.end(), '\n'), 1) << plot.err;
    EXPECT_NE(plot.err.find("hmcr: error: plot: no Python with matplotlib"), std::string::npos);
    EXPECT_TRUE(snapshot(dir()) == before);
}

// A plotting script that fails (a broken matplotlib) costs the plots, not the finished study:
// exit code 0, its tables written, and one warning on how to draw the plots, with the script's
// own last word. `hmcr plot` then fails in one line, exit code 2, not as an internal error.
TEST_F(HostileStudy, AFailingPlotScriptLeavesTheStudyWhole) {
    const std::filesystem::path python = m_temp.write(
        "broken-python",
        "#!/bin/sh\n[ \"$1\" = -c ] && exit 0\necho 'Traceback' >&2\necho 'Error: broken' >&2\n"
        "exit 1\n");
    std::filesystem::permissions(python, std::filesystem::perms::owner_exec,
                                 std::filesystem::perm_options::add);
    const std::string launcher = "env HMCR_PYTHON=" + python.string() + " ";
    const CliRun study = run_launched(launcher, kStudy, dir(), 60);
    EXPECT_EQ(study.exit_code, 0) << study.err;
    EXPECT_TRUE(std::filesystem::exists(dir() / "st" / "table.tex"));
    EXPECT_EQ(study.err.find("Traceback"), std::string::npos) << study.err;
    EXPECT_NE(study.err.find("hmcr: warning: plots not drawn: the plotting script "),
              std::string::npos)
        << study.err;
    EXPECT_NE(study.err.find("(exit 1: Error: broken); draw them with `hmcr plot st`\n"),
              std::string::npos)
        << study.err;
    const CliRun plot = run_launched(launcher, "plot st", dir(), 60);
    EXPECT_EQ(plot.exit_code, 2) << plot.err;
    EXPECT_EQ(std::count(plot.err.begin(), plot.err.end(), '\n'), 1) << plot.err;
    EXPECT_EQ(plot.err.find("internal error"), std::string::npos) << plot.err;
    EXPECT_NE(plot.err.find("hmcr: error: plot: the plotting script "), std::string::npos)
        << plot.err;
    EXPECT_NE(plot.err.find("(exit 1: Error: broken)\n"), std::string::npos) << plot.err;
}

// Values the cell checks accept, at the ends of double's range: an object error of 1e308 (its
// error bars overflow) and every real value 5e-324 (its axis limits underflow to 0). The
// plotting script draws them (what a log axis cannot show, it leaves out).
TEST_F(HostileStudy, ThePlotScriptDrawsExtremeValues) {
    if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0) {
        GTEST_SKIP() << "no matplotlib in /usr/bin/python3";
    }
    // One-sided plates, whose budgets are reached: cells with object errors to spoil.
    m_temp.write("one.json", with(read_file(dir() / "plates.json"), "{", R"({"sides": 1, )"));
    accepted("reference one.json --max-area 0.1 --rays 20000 -q -o ref1");
    accepted(
        "study one.json --reference ref1 --budgets 20,40 --oracles power,kl --seeds 2 -q -o st");
    const nlohmann::json table = nlohmann::json::parse(read_file(dir() / "st" / "table.json"));
    nlohmann::json huge = table, tiny = table;
    for (std::size_t k = 0; k < table["cells"].size(); ++k) {
        nlohmann::json& error = huge["cells"][k]["object_error"];
        if (error.is_null()) continue;
        error["relative_l2"] = k % 2 ? 1e308 : 1e307;
        error["standard_error"] = 1e307;
    }
    const std::function<void(nlohmann::json&)> smallest = [&](nlohmann::json& j) {
        if (j.is_number_float()) j = 5e-324;
        if (!j.is_structured()) return;
        for (auto& item : j) smallest(item);
    };
    for (auto& cell : tiny["cells"]) smallest(cell);
    for (const nlohmann::json* t : {&huge, &tiny}) {
        m_temp.write("st/table.json", t->dump());
        std::filesystem::remove(dir() / "st" / "plots" / "error_vs_elements.png");
        const CliRun plot = run_launched("env HMCR_PYTHON=/usr/bin/python3 ", "plot st", dir(), 60);
        EXPECT_EQ(plot.exit_code, 0) << plot.err;
        EXPECT_EQ(plot.err, "");
        EXPECT_TRUE(std::filesystem::exists(dir() / "st" / "plots" / "error_vs_elements.png"));
    }
}

// The plotting script, run by hand on plot data that names a figure by a path: it writes
// nothing, and says so in one line (exit code 2).
TEST_F(Hostile, ThePlotScriptNamesNoFileOutsideItsFolder) {
    m_temp.write("st/plots/plot_data.json", R"({"figures": [{"name": "../../escaped", "panels": [
        {"type": "bars", "title": "t", "y_label": "y", "categories": ["a"],
         "groups": [{"name": "g", "values": [{"y": 1, "y_se": null}]}]}]}]})");
    const auto before = snapshot(dir());
    const std::string script =
        (std::filesystem::path(HMCR_SCENE_DIR).parent_path() / "scripts" / "plot_study.py")
            .string();
    const std::string cmd = "cd '" + dir().string() + "' && /usr/bin/python3 '" + script +
                            "' st/plots/plot_data.json 2>.err";
    const int status = std::system(cmd.c_str());
    if (WEXITSTATUS(status) == 3) GTEST_SKIP() << "no matplotlib in /usr/bin/python3";
    const std::string err = read_file(dir() / ".err");
    std::filesystem::remove(dir() / ".err");
    EXPECT_EQ(WEXITSTATUS(status), 2) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("figure name '../../escaped'"), std::string::npos) << err;
    EXPECT_TRUE(snapshot(dir()) == before);
}

}  // namespace
}  // namespace hmcr::test
