// SPDX-License-Identifier: Apache-2.0
// Hostile options: values that once were accepted and ran for ever or gave a silent wrong
// result, and lists with a value twice.
#include <fmt/format.h>

#include <regex>

#include "tests/hostile/hostile.h"
#include "tests/support/hmcr_child.h"

namespace hmcr::test {
namespace {

TEST_F(Hostile, NumbersOutOfRangeOrNotNumbersAreRefused) {
    plates();
    const std::pair<std::string, std::string> cases[] = {
        {"--epsilon nan", "not a finite number"},
        {"--epsilon -1", "epsilon must be positive"},
        {"--rays 18446744073709551615", "rays must be in 1..1e15"},
        {"--rays 0", "rays must be in 1..1e15"},
        {"--rays 1.5", "not a whole number"},
        {"--budget 0", "budget must be a positive leaf count"},
        {"--budget-tolerance -1", "budget-tolerance must be in (0, 1)"},
        {"--budget-tolerance nan", "--budget-tolerance: 'nan' is not a finite number"},
        {"--stop 0", "stop must be in (0, 1)"},
        {"--min-area inf", "not a finite number"},
        {"--max-depth 25", "max-depth must be in 0..24"},
        {"--lines 0", "lines must be in 1..4096"},
        {"--max-elements 0", "max-elements must be at least 1"},
        {"--crease-angle 200", "crease-angle must be in [0, 180]"},
        {"--oracle nope", "oracle must be one of power"},
        {"--progress loud", "progress must be auto, bar, lines or none"},
    };
    for (const auto& [option, needle] : cases) {
        refused("solve plates.json -o out.vtp " + option, needle);
    }
}

// Every real option of every command, as its help lists them (FLOAT), refuses what CLI11 reads as
// a number but is none: nan, inf and 1e309 (infinity), where the options are parsed.
TEST_F(Hostile, EveryRealOptionRefusesValuesThatAreNotFinite) {
    plates();
    const std::pair<std::string, std::string> commands[] = {
        {"solve", "plates.json -o x.vtp"},
        {"render", "x.vtp --scene plates.json -o x.png"},
        {"reference", "plates.json -o r"},
        {"error", "x.vtp --scene plates.json --reference r"},
        {"study", "plates.json --reference r -o s"},
        {"info", "plates.json"},
        {"trace", "plates.json -o x.png"},
        {"trace-reference", "plates.json -o r"},
    };
    std::size_t options = 0;
    for (const auto& [command, args] : commands) {
        const std::string help = run_hmcr(command + " --help", dir()).out;
        const std::regex real(R"((--[a-z-]+) FLOAT)");
        for (auto it = std::sregex_iterator(help.begin(), help.end(), real);
             it != std::sregex_iterator(); ++it) {
            const std::string flag = (*it)[1];
            ++options;
            for (const char* value : {"nan", "inf", "1e309"}) {
                refused(command + " " + args + " " + flag + " " + value,
                        flag + ": '" + value + "' is not a finite number");
            }
        }
    }
    EXPECT_GE(options, 20u);  // the help's FLOAT options were found
}

// A subnormal number (4.9e-324 is read as 5e-324, the smallest) is what the ray tracing threads
// flush to 0, and a range check took it for 0: "must be in (0, 1], got 5e-324". Refused as what
// it is, on the command line and in a scene file; the smallest normal number is a value.
TEST_F(Hostile, SubnormalNumbersAreRefusedAsSuch) {
    plates();
    const std::string reason =
        " is a subnormal number, which hmcr's ray tracing computes as 0 (the smallest normal "
        "number is 2.2e-308)";
    for (const char* option : {"--refine-share", "--epsilon", "--stop", "--min-area"}) {
        refused(std::string("solve plates.json -o x.vtp ") + option + " 4.9e-324",
                std::string(option) + ": '4.9e-324'" + reason);
    }
    refused("trace plates.json -o x.png --sampler kl --threshold 1e-310",
            "--threshold: '1e-310'" + reason);
    m_temp.write("sub.json", with(kPlatesJson, "{", R"({"solver": {"stop": 4.9e-324}, )"));
    refused("solve sub.json -o x.vtp", "sub.json: solver.stop: stop: 5e-324" + reason);
    accepted("solve plates.json -o x.vtp -q --rays 1000 --refine-share 2.3e-308");
}

TEST_F(Hostile, TheElementLimitStopsAGrowingHierarchy) {
    plates();
    refused(
        "solve plates.json -o out.vtp --oracle power --epsilon 1e-12 --rays 20000 "
        "--max-elements 1000",
        "would grow beyond --max-elements 1000");
}

// Every patch is an element from the start: a limit below the patch count is refused before
// any work, whether or not the solve would refine (a huge epsilon refines nothing).
TEST_F(Hostile, TheElementLimitCountsThePatchRoots) {
    plates();
    for (const char* solve : {"solve plates.json -o out.vtp --max-elements 1",
                              "solve plates.json -o out.vtp --max-elements 1 --epsilon 1e30",
                              "solve plates.json -o out.vtp --max-elements 1 --budget 2"}) {
        refused(solve, "the scene's patches alone are 2 elements, more than --max-elements 1");
    }
    std::filesystem::create_directories(dir() / "ref");
    refused("study plates.json --reference ref -o st --budgets 2 --max-elements 1",
            "the scene's patches alone are 2 elements");
}

// A scene of 90,000 patches under --max-elements 1000: refused once loaded, in the time and
// memory of the load, with advice that can help (not "refine less").
TEST_F(Hostile, ASceneOfMorePatchesThanTheElementLimitIsRefusedAtOnce) {
    constexpr int n = 300;
    std::string obj = "mtllib plates.mtl\nusemtl receiver\n";
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) obj += fmt::format("v {} {} 0\n", i, j);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1;
            obj += fmt::format("f {} {} {} {}\n", a, a + 1, a + n + 2, a + n + 1);
        }
    obj += "v 0 0 9\nv 300 0 9\nv 300 300 9\nv 0 300 9\nusemtl emitter\nf -1 -2 -3 -4\n";
    plates(obj);
    const auto before = snapshot(dir());
    HmcrChild child("solve plates.obj -o out.vtp --max-elements 1000", dir(), 60);
    const ChildExit e = child.wait();
    EXPECT_EQ(e.code, 2) << e.err;
    EXPECT_NE(e.err.find("patches alone are 90001 elements, more than --max-elements 1000: "
                         "raise it to at least 90001"),
              std::string::npos)
        << e.err;
    EXPECT_EQ(e.err.find("refine less"), std::string::npos) << e.err;
    EXPECT_LT(e.seconds, 10.0);
    EXPECT_LT(e.peak_bytes, 300u << 20);
    EXPECT_TRUE(snapshot(dir()) == before);
}

TEST_F(Hostile, RenderOptionsAreChecked) {
    plates();
    accepted("solve plates.json --rays 2000 -q -o p.vtp");
    for (const char* e : {"-1", "0"}) {
        refused("render p.vtp --scene plates.json -o x.png --exposure " + std::string(e),
                "exposure must be a positive number, got " + std::string(e));
    }
    refused("render p.vtp --scene plates.json -o x.png --samples 0", "samples must be in 1..16");
    refused("render p.vtp --scene plates.json -o x.jpg", "output must be a .png file");
    refused("render p.vtp --scene plates.json --view top -o x.png", "no view 'top' (views: side)");
}

TEST_F(Hostile, InfoRefusesWhatCannotFitInMemory) {
    plates();
    refused("info plates.json --lines 1e12", "would need about 4000.0 GB of memory");
    refused("info plates.json --lines 1e12 --method global", "GB of memory");
    refused("info plates.json --lines 10", "lines must be at least 16");
    refused("info plates.json --method globl", "unknown line method 'globl'");
}

TEST_F(Hostile, StudyListsWithAValueTwiceAreRefused) {
    plates();
    const std::string study = "study plates.json --reference ref -o st --seeds 1 ";
    std::filesystem::create_directories(dir() / "ref");
    refused(study + "--budgets 5 --oracles power,power", "oracle power is given twice");
    refused(study + "--budgets 5 --oracles all,kl", "oracle kl is given twice");
    refused(study + "--budgets 500,500", "budget 500 is given twice");
    refused(study + "--budgets 500,,600", "empty item in the list");
    // An empty item at either end is refused alike, in every list.
    refused(study + "--budgets 20,", "empty item in the list '20,'");
    refused(study + "--budgets ,20", "empty item in the list ',20'");
    refused(study + "--budgets , ", "empty item in the list ','");
    refused(study + "--budgets 5 --oracles kl,", "empty item in the list 'kl,'");
    refused(study + "--samplers uniform, --spp 16", "empty item in the list 'uniform,'");
    refused(study + "--samplers uniform --spp 16,", "empty item in the list '16,'");
    refused(study + "--samplers uniform --spp 16,32,", "empty item in the list '16,32,'");
}

// --columns names the tables' columns of the study's kind: another name is refused in one line
// naming the valid ones, before the reference is read or any cell computed ("ref" is empty).
TEST_F(Hostile, StudyColumnsOfAnotherKindOrTwiceAreRefused) {
    plates();
    const std::string study = "study plates.json --reference ref -o st --seeds 1 ";
    std::filesystem::create_directories(dir() / "ref");
    refused(study + "--budgets 5 --columns psnr_p,spp",
            "study: unknown column 'spp' of a meshing study's tables (valid: seeds, rmse_a, "
            "rmse_p, psnr_a, psnr_p, object_error, mesh_psnr_p, mesh_object_error, finer_share, "
            "leaves, epsilon, seconds, all)");
    refused(study + "--samplers uniform --columns object_error",
            "study: unknown column 'object_error' of a sampling study's tables (valid: seeds, "
            "rmse_a, rmse_p, psnr_a, psnr_p, spp, max_spp, rays, seconds, all)");
    refused(study + "--budgets 5 --columns leaves,all", "study: column leaves is given twice");
    refused(study + "--budgets 5 --columns leaves,", "empty item in the list 'leaves,'");
}

}  // namespace
}  // namespace hmcr::test
