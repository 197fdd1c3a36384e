// SPDX-License-Identifier: Apache-2.0
// The promise of docs/usage.md#bad-input that no command writes outside the file or folder it
// was given: every command is run once as a user would, with its outputs in folders of their
// own, and once on a scene whose view names point out of those folders; the working folder is
// compared file by file before and after.
#include <unistd.h>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

// A command and the outputs it was given: a file ("o1/x.vtp": that file and the files
// documented beside it, o1/x.*), or a folder ("o3/": anything below it).
struct Given {
    std::string args;
    std::vector<std::string> outputs;
};

bool within(const std::string& file, const std::string& output) {
    if (output.ends_with("/")) return file.starts_with(output);
    const fs::path out(output), f(file);
    const std::string stem = out.stem().string();
    return f.parent_path() == out.parent_path() && f.filename().string().starts_with(stem);
}

class HostileConfinement : public Hostile {
protected:
    void SetUp() override {
        plates(kPlatesObj, kPlatesMtl, scene_with_view("side"));
        accepted("reference plates.json --max-area 0.5 --rays 2000 -q -o in/ref");
        accepted("trace-reference plates.json --spp 2 -q -o in/tref");
        accepted("solve plates.json --rays 2000 -q -o in/s.vtp");
    }
    static std::string scene_with_view(const std::string& name) {
        return R"({"mesh": "plates.obj", "views": [{"name": ")" + name +
               R"(", "position": [2.8, 0.5, 0.5], "look_at": [0.5, 0.5, 0.5], "width": 8,
                   "height": 8}]})";
    }
    // Runs the command and expects every file it added or changed to be one of its outputs.
    void confined(const Given& g) const {
        const auto before = snapshot(dir());
        const CliRun r = run_hmcr(g.args, dir());
        EXPECT_EQ(r.exit_code, 0) << g.args << "\n" << r.err;
        const auto after = snapshot(dir());
        for (const auto& entry : after) {
            const std::string& file = entry.first;
            const auto old = before.find(file);
            if (old != before.end() && old->second == entry.second) continue;
            EXPECT_TRUE(std::any_of(g.outputs.begin(), g.outputs.end(),
                                    [&](const std::string& o) { return within(file, o); }))
                << g.args << " wrote " << file;
        }
        for (const auto& [file, bytes] : before) {
            EXPECT_TRUE(after.count(file)) << g.args << " removed " << file;
        }
    }
};

const std::vector<Given> kCommands = {
    {"solve plates.json --rays 2000 -q -o o/1/x.vtp", {"o/1/x.vtp"}},
    {"render in/s.vtp --scene plates.json -o o/2/x.png --pfm o/2b/y.pfm",
     {"o/2/x.png", "o/2b/y.pfm"}},
    {"reference plates.json --max-area 0.5 --rays 2000 -q -o o/3", {"o/3/"}},
    {"trace plates.json --spp 2 -q -o o/4/x.png --pfm o/4b/y.pfm", {"o/4/x.png", "o/4b/y.pfm"}},
    {"trace-reference plates.json --spp 2 -q -o o/5", {"o/5/"}},
    {"study plates.json --reference in/ref --budgets 4 --oracles power --rays 2000 "
     "--mesh-rays 2000 --seeds 1 -q -o o/6",
     {"o/6/"}},
    {"study plates.json --reference in/tref --samplers uniform --spp 2 --seeds 1 -q -o o/7",
     {"o/7/"}},
    {"plot o/6", {"o/6/"}},
    {"info plates.json --lines 1000", {}},
    {"oracles", {}},
    {"samplers", {}},
    {"scenes", {}},
};

TEST_F(HostileConfinement, EveryCommandWritesOnlyWhatItWasGiven) {
    for (const Given& g : kCommands) confined(g);
}

// Names a scene file may give its views, each of which would lead a reference's views/NAME.pfm
// out of its folder, hide it, or break a message in two.
TEST_F(HostileConfinement, NoViewNameLeadsAWriteOutOfItsFolder) {
    const fs::path outside =
        fs::temp_directory_path() / ("hmcr-escaped-" + std::to_string(getpid()));
    for (const std::string& name :
         {std::string("../../ESCAPED"), outside.string(), std::string(""), std::string("a\\nb"),
          std::string(".hidden"), std::string(65, 'v')}) {
        m_temp.write("plates.json", scene_with_view(name));
        for (const Given& g : kCommands) {
            if (g.args.find("plates.json") == std::string::npos) continue;
            refused(g.args, "cannot name a file");
        }
        EXPECT_FALSE(fs::exists(outside.string() + ".pfm")) << name;
    }
}

}  // namespace
}  // namespace hmcr::test
