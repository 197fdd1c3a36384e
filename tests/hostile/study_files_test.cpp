// Hostile study folders: a cell file cut short, emptied or holding values no study makes is
// computed again, not fatal and not tabled; a folder made with other settings is refused, not
// mixed into one table; a study's size and seeds are bounded before anything is written.
#include <nlohmann/json.hpp>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

class HostileStudy : public Hostile {
protected:
    void SetUp() override {
        plates(kPlatesObj, kPlatesMtl,
               R"({"mesh": "plates.obj", "solver": {"rays": 20000}, "views": [{"name": "side",
                   "position": [2.8, 0.5, 0.5], "look_at": [0.5, 0.5, 0.5], "width": 32,
                   "height": 32}]})");
        accepted("reference plates.json --max-area 0.1 --rays 20000 -q -o ref");  // rays its own
    }
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
            << pointer << "\n" << r.err;
        EXPECT_NE(r.err.find(pointer.substr(pointer.rfind('/') + 1)), std::string::npos) << r.err;
        EXPECT_EQ(nlohmann::json::parse(read_file(cell(1)))["leaves"], good["leaves"]) << pointer;
    }
}

TEST_F(HostileStudy, TheCellCountAndTheSeedsAreBounded) {
    refused("study plates.json --reference ref --budgets 20 --oracles all --seeds 2000 -o big",
            "7 x 2000 seeds = 14000 cells");
    refused("study plates.json --reference ref --samplers uniform --seeds 10001 -o big",
            "1 x 10001 seeds = 10001 cells, more than the 10000 a study may have");
    refused("study plates.json --reference ref --budgets 20 --oracles power "
            "--first-seed 18446744073709551614 --seeds 3 -o big",
            "pass the largest seed");
    refused("study plates.json --reference ref --samplers uniform "
            "--first-seed 18446744073709551615 --seeds 2 -o big",
            "pass the largest seed");
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

}  // namespace
}  // namespace hmcr::test
