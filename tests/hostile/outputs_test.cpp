// SPDX-License-Identifier: Apache-2.0
// Hostile outputs: no command writes over one of its own inputs, and an output that cannot be
// written is refused before the work, in hmcr's words: every file of the command's set is
// checked first, so that a refusal leaves none of them.
#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

std::string with_mtllib(const std::string& name) {
    std::string obj = kPlatesObj;
    obj.replace(obj.find("plates.mtl"), 10, name);
    return obj;
}

TEST_F(Hostile, NoCommandWritesOverItsInputs) {
    plates();
    // solve's summary goes beside the .vtp: plates.vtp would put it over plates.json.
    refused("solve plates.json -o plates.vtp", "is an input of this command");
    refused("solve plates.obj -o plates.obj", "output must be a .vtp file");
    accepted("solve plates.json --rays 2000 -q -o p.vtp");
    refused("render p.vtp --scene plates.json -o p.png --pfm p.vtp", "must be a .pfm file");
    m_temp.write("same.png", "");
    refused("render p.vtp --scene plates.json -o x.png --pfm x.png", "must be a .pfm file");
    std::filesystem::create_symlink(dir() / "p.vtp", dir() / "link.pfm");
    refused("render p.vtp --scene plates.json -o x.png --pfm link.pfm", "is an input");
    // The ParaView state goes beside the .vtp too: never over a material library of that name.
    plates(with_mtllib("m.pvsm"));
    m_temp.write("m.pvsm", kPlatesMtl);
    refused("solve plates.obj -o m.vtp", "is an input of this command");
}

// The bundled layout, DIR/X.obj beside DIR/X.json: a solve of the mesh alone names its summary
// DIR/X.json, the scene file, which is no input of that run; a trace's IMAGE.json alike. Refused;
// an earlier summary, or a file that is no JSON, is replaced as ever.
TEST_F(Hostile, NoSummaryReplacesASceneFileBesideIt) {
    plates();
    refused("solve plates.obj --rays 2000 -q -o plates.vtp",
            "plates.json: is a scene file (it names a \"mesh\")");
    m_temp.write("v/side.json", R"({"mesh": "../plates.obj"})");
    refused("trace plates.obj --spp 1 -q -o v/side.png", "v/side.json: is a scene file");
    accepted("solve plates.obj --rays 2000 -q -o p.vtp");
    accepted("solve plates.obj --rays 2000 -q -o p.vtp");  // over its own summary
    m_temp.write("q.json", "not json");
    accepted("solve plates.obj --rays 2000 -q -o q.vtp");
    EXPECT_NE(read_file(dir() / "q.json").find("hmcr_version"), std::string::npos);
}

TEST_F(Hostile, AStudyMayNotWriteIntoItsReference) {
    plates();
    std::filesystem::create_directories(dir() / "ref");
    const std::string study = "study plates.json --budgets 5 --oracles power --reference ref ";
    refused(study + "-o ref", "is, holds or lies in the input folder");
    refused(study + "-o ref/inside", "is, holds or lies in the input folder");
    refused(study + "-o .", "is, holds or lies in the input folder");
}

TEST_F(Hostile, OutputsThatCannotBeWrittenAreRefusedFirst) {
    plates();
    m_temp.write("file", "x");
    refused("reference plates.json --rays 100000000 -o file",
            "cannot write file: it is not a folder");
    refused("study plates.json --budgets 5 --reference ref -o file", "it is not a folder");
    refused("solve plates.json --rays 100000000 -o /proc/x.vtp", "cannot write /proc/x.vtp");
    refused("solve plates.json -o file/x.vtp", "cannot write file/x.vtp");
    std::filesystem::create_directory(dir() / "x.vtp");
    refused("solve plates.json -o x.vtp", "it is a folder");
}

// Each command is given work of minutes: a refusal that came after it would hit the time limit.
TEST_F(Hostile, EveryFileOfASetIsCheckedBeforeTheWork) {
    plates();
    const std::string long_name(251, 'n');  // NAME.vtp and NAME.png fit in 255 bytes
    std::filesystem::create_directories(dir() / "d" / "x.json");
    refused("solve plates.json --rays 1e12 -q -o d/x.vtp", "cannot write d/x.json: it is a folder");
    refused("solve plates.json --rays 1e12 -q -o d/" + long_name + ".vtp",
            ".json: its name is 256 bytes long, more than 255");
    refused("trace plates.json --spp 100000 -q -o d/x.png",
            "cannot write d/x.json: it is a folder");
    refused("trace plates.json --spp 100000 -q -o d/" + long_name + ".png",
            "-density.png: its name is 263 bytes long, more than 255");
    std::filesystem::create_directories(dir() / "ref" / "views" / "side.png");
    refused("reference plates.json --rays 1e12 -q -o ref", "cannot write ref/views/side.png");
    refused("trace-reference plates.json --spp 100000 -q -o ref",
            "cannot write ref/views/side.png");
}

TEST_F(Hostile, AStudysCellFilesAreCheckedBeforeTheFirstCell) {
    plates();
    accepted("reference plates.json --max-area 0.5 --rays 2000 -q -o ref");
    std::filesystem::create_directories(dir() / "st" / "cells" / "plates-power-B4-s2.json");
    refused(
        "study plates.json --reference ref --budgets 4 --oracles power --seeds 2 "
        "--rays 1e12 -q -o st",
        "cannot write st/cells/plates-power-B4-s2.json: it is a folder");
    std::filesystem::create_directories(dir() / "st2" / "images" / "plates-kl-B4-s1-side.png");
    refused(
        "study plates.json --reference ref --budgets 4 --oracles power,kl --seeds 1 "
        "--rays 1e12 -q -o st2",
        "cannot write st2/images/plates-kl-B4-s1-side.png: it is a folder");
}

// The folders a run makes for its outputs go with them when it is stopped.
TEST_F(Hostile, AnInterruptedReferenceLeavesNoFolder) {
    const int status = interrupted("reference cube-room --max-area 0.01 --rays 1e9 -q -o out/ref",
                                   dir(), SIGTERM, std::chrono::milliseconds(700));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << read_file(dir() / ".stderr");
    std::filesystem::remove(dir() / ".stdout");
    std::filesystem::remove(dir() / ".stderr");
    EXPECT_TRUE(std::filesystem::is_empty(dir()));
}

// A hang-up (the terminal closed) stops a run as SIGTERM does: exit code 129, one line, no
// output and no lock file left. Under nohup (SIGHUP ignored from the start) the run goes on.
TEST_F(Hostile, AHangUpEndsARunCleanlyUnlessIgnored) {
    plates();
    const auto wait_for_lock = [&] {
        for (int i = 0; i < 1500 && !std::filesystem::exists(dir() / "out" / ".x.pvsm.lock"); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
    };
    {
        HmcrChild solve("solve plates.json --rays 1e12 -q -o out/x.vtp", dir(), 60);
        wait_for_lock();
        solve.signal(SIGHUP);
        const ChildExit e = solve.wait();
        EXPECT_EQ(e.code, 128 + SIGHUP) << e.err;
        EXPECT_EQ(e.err, "hmcr: error: interrupted by SIGHUP; no partial output left\n");
        EXPECT_LT(e.seconds, 5.0);
    }
    EXPECT_FALSE(std::filesystem::exists(dir() / "out"));  // nor its lock files
    struct sigaction ignore {
    }, before{};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGHUP, &ignore, &before);  // as nohup starts it
    HmcrChild solve("solve plates.json --rays 1e12 -q -o out/x.vtp", dir(), 60);
    sigaction(SIGHUP, &before, nullptr);
    wait_for_lock();
    solve.signal(SIGHUP);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_TRUE(std::filesystem::exists(dir() / "out" / ".x.pvsm.lock"));  // still running
    solve.signal(SIGTERM);
    EXPECT_EQ(solve.wait().code, 128 + SIGTERM);
}

TEST_F(Hostile, RenderIsQuietWhenAsked) {
    plates(kPlatesObj, std::string(kPlatesMtl) + "frobnicate 1\n");  // ignored, with a warning
    accepted("solve plates.json --rays 2000 -q -o p.vtp");
    const CliRun loud = accepted("render p.vtp --scene plates.json -o p.png");
    EXPECT_NE(loud.err.find("warning"), std::string::npos) << loud.err;
    const CliRun quiet = accepted("render p.vtp --scene plates.json -q -o q.png");
    EXPECT_EQ(quiet.err + quiet.out, "");
}

}  // namespace
}  // namespace hmcr::test
