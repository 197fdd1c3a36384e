// SPDX-License-Identifier: Apache-2.0
// Hostile JSON files: a key given twice (nlohmann kept the last, so a stray copy of a setting won
// silently) is refused with its line in scene files and reference.json, and makes a study cell
// unreadable; a reference.json member of the wrong type is named by its path, not in nlohmann's
// words (docs/usage.md#bad-input).
#include <filesystem>
#include <string>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

TEST_F(Hostile, SceneFileKeysGivenTwiceAreRefusedWithTheirLine) {
    plates(kPlatesObj, kPlatesMtl, "{\"mesh\": \"plates.obj\",\n \"mesh\": \"other.obj\"}");
    refused("info plates.json",
            "plates.json:2: key 'mesh' is given twice in one object (first at line 1)");
    plates(kPlatesObj, kPlatesMtl,
           "{\"mesh\": \"plates.obj\", \"views\": [{\"name\": \"side\",\n"
           "  \"position\": [2.8, 0.5, 0.5], \"look_at\": [0.5, 0.5, 0.5],\n"
           "  \"width\": 32,\n  \"height\": 32, \"width\": 64}]}");
    refused("trace plates.json -o x.png",
            "plates.json:4: key 'width' is given twice in one object (first at line 3)");
    // The same key in two objects is two keys.
    plates(kPlatesObj, kPlatesMtl,
           R"({"mesh": "plates.obj", "views": [{"name": "a", "position": [2.8, 0.5, 0.5],
               "look_at": [0.5, 0.5, 0.5]}, {"name": "b", "position": [2.8, 0.5, 0.6],
               "look_at": [0.5, 0.5, 0.5]}]})");
    accepted("info plates.json --lines 1000");
}

// A reference as `trace --reference` reads it, for its exposures.
class HostileReference : public Hostile {
protected:
    void reference(const std::string& json) const { m_temp.write("ref/reference.json", json); }
    static constexpr const char* kTrace = "trace plates.json -o x.png --spp 1 --reference ref";
};

TEST_F(HostileReference, KeysGivenTwiceAreRefusedWithTheirLine) {
    plates();
    reference(
        "{\"reference\": {\"views\": {\"side\": {\n"
        "  \"exposure\": 1.5,\n  \"exposure\": 3}}}}");
    refused(kTrace,
            "ref/reference.json:3: key 'exposure' is given twice in one object (first at "
            "line 2)");
    reference("{\"reference\": {\"views\": {\"side\": {\"exposure\": 1.5}}}}");
    accepted(kTrace + std::string(" -q"));
}

// nlohmann's "type must be number, but is string" named no key.
TEST_F(HostileReference, MembersOfTheWrongTypeAreNamed) {
    plates();
    const std::pair<std::string, std::string> cases[] = {
        {R"({"reference": {"views": {"side": {"exposure": "bright"}}}})",
         "ref/reference.json: reference.views.side.exposure: must be a number, not string"},
        {R"({"reference": {"views": {"side": {}}}})",
         "ref/reference.json: reference.views.side.exposure: missing"},
        {R"({"reference": {"views": []}})",
         "ref/reference.json: reference.views: must be an object, not array"},
        {R"({"reference": 7})", "ref/reference.json: reference: must be an object, not number"},
        {R"([])", "ref/reference.json: the file: must be an object, not array"},
    };
    for (const auto& [json, needle] : cases) {
        reference(json);
        refused(kTrace, needle);
    }
    reference(R"({"reference": {"kind": 1, "views": {"side": {"exposure": 1.5}}}})");
    refused("study plates.json --reference ref --budgets 20 --oracles power -o st",
            "ref/reference.json: reference.kind: must be a string, not number");
}

// A study cell with a key given twice is unreadable: computed again, with a note naming the line.
TEST_F(Hostile, CellFileKeysGivenTwiceMakeTheCellComputedAgain) {
    plates();
    accepted("reference plates.json --max-area 0.1 --rays 20000 --samples 1 -q -o ref");
    const std::string study =
        "study plates.json --reference ref --budgets 20 --oracles power --seeds 1 --rays 20000 "
        "--mesh-rays 0 --samples 1 -o st";
    accepted(study);
    const std::filesystem::path cell = dir() / "st" / "cells" / "plates-power-B20-s1.json";
    std::string text = read_file(cell);
    text.insert(text.find('{') + 1, "\n  \"seed\": 2,");
    m_temp.write("st/cells/plates-power-B20-s1.json", text);
    const CliRun r = accepted(study);
    EXPECT_NE(r.err.find("key 'seed' is given twice in one object"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("computing it again"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hmcr::test
