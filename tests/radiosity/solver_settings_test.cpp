// SPDX-License-Identifier: Apache-2.0
// The settings table: a scene file's "solver" object is checked key by key and value by value,
// and the summary names every setting.
#include "radiosity/solver_settings.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/error.h"

namespace hmcr::test {
namespace {

using nlohmann::json;

// The error of applying `solver` to default options, or "" when it applies.
std::string solver_error(const json& solver) {
    SolverOptions o;
    try {
        apply_scene_settings(solver, "scene.json", o);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SolverSettings, EveryDefaultIsValid) {
    EXPECT_NO_THROW(validate(SolverOptions{}));
    for_each_setting([](const auto& s) { EXPECT_TRUE(s.valid(s.default_value)) << s.name; });
}

TEST(SolverSettings, FlagsAreTheNamesWithDashes) {
    std::vector<std::string> flags;
    for_each_setting([&](const auto& s) { flags.push_back(s.flag()); });
    EXPECT_NE(std::find(flags.begin(), flags.end(), "--min-area"), flags.end());
    EXPECT_NE(std::find(flags.begin(), flags.end(), "--cache-mb"), flags.end());
}

TEST(SolverSettings, SceneValuesApply) {
    SolverOptions o;
    apply_scene_settings(json{{"oracle", "power"}, {"rays", 5000}, {"stop", 0.05}, {"lines", 4}},
                         "scene.json", o);
    EXPECT_EQ(o.oracle->name(), "power");
    EXPECT_EQ(o.rays, 5000u);
    EXPECT_EQ(o.stop, 0.05);
    EXPECT_EQ(o.lines, 4);
    EXPECT_EQ(o.max_depth, SolverOptions{}.max_depth);  // not given: untouched
}

// Whole numbers read from a file's text are JSON's unsigned ones: a signed setting takes them.
TEST(SolverSettings, SignedSettingsTakeTheWholeNumbersOfAFile) {
    SolverOptions o;
    apply_scene_settings(json::parse(R"({"lines": 4, "max_depth": 3})"), "scene.json", o);
    EXPECT_EQ(o.lines, 4);
    EXPECT_EQ(o.max_depth, 3);
    for (const char* text :
         {R"({"max_depth": 4294967296})", R"({"lines": 18446744073709551615})"}) {
        EXPECT_NE(solver_error(json::parse(text)).find("must be a whole number in range"),
                  std::string::npos)
            << text;
    }
}

// Every bad value is refused with the file and the key, never rounded, wrapped or clamped.
TEST(SolverSettings, BadSceneValuesAreRefusedWithFileAndKey) {
    for (const json& rays : {json(-5), json(1e30), json(2.5), json("abc"), json(0)}) {
        const std::string e = solver_error({{"rays", rays}});
        EXPECT_EQ(e.rfind("scene.json: solver.rays: ", 0), 0u) << rays << ": " << e;
    }
    EXPECT_NE(solver_error({{"seed", -1}}).find("solver.seed: must be a whole number"),
              std::string::npos);
    EXPECT_NE(solver_error({{"stop", 2}}).find("solver.stop: stop must be in (0, 1), got 2"),
              std::string::npos);
    EXPECT_NE(solver_error({{"epsilon", -1}}).find("solver.epsilon: epsilon must be positive"),
              std::string::npos);
    EXPECT_NE(solver_error({{"max_depth", 1.5}}).find("solver.max_depth"), std::string::npos);
    EXPECT_NE(solver_error({{"oracle", "nope"}}).find("one of power, ks"), std::string::npos);
    EXPECT_NE(solver_error({{"link_weight", "most"}}).find("unshot or total, got 'most'"),
              std::string::npos);
    EXPECT_NE(solver_error({{"oracle", 3}}).find("solver.oracle: must be a string"),
              std::string::npos);
}

// Keys a scene may not set: unknown ones, and properties of a run rather than of a scene.
TEST(SolverSettings, UnknownAndRunOnlyKeysAreRefused) {
    EXPECT_NE(
        solver_error({{"ray", 5}}).find("scene.json: solver: unknown setting 'ray' (settings: "),
        std::string::npos);
    EXPECT_NE(solver_error({{"threads", 2}}).find("unknown setting 'threads'"), std::string::npos);
    EXPECT_NE(solver_error({{"uniform_max_area", 1}}).find("unknown setting"), std::string::npos);
    EXPECT_NE(solver_error(json::array()).find("must be a JSON object"), std::string::npos);
}

TEST(SolverSettings, SummaryNamesEverySetting) {
    const json j = settings_json(SolverOptions{});
    std::size_t n = 0;
    for_each_setting([&](const auto& s) {
        ++n;
        EXPECT_TRUE(j.contains(std::string(s.name))) << s.name;
    });
    EXPECT_EQ(j.size(), n);
    EXPECT_EQ(j["rays"], SolverOptions{}.rays);
    EXPECT_EQ(j["oracle"], "kl");  // named settings by their names
    EXPECT_EQ(j["link_weight"], "unshot");
}

}  // namespace
}  // namespace hmcr::test
