// SPDX-License-Identifier: Apache-2.0
#include "common/text_file.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

std::string error_of(const std::filesystem::path& path) {
    try {
        read_json_file(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// A JSON syntax error names file and line, and the token nlohmann quotes ("last read") is cut
// short and stays on one line, however long the bad literal (found by the reference fuzzer).
TEST(ReadJsonFile, ASyntaxErrorIsOneShortLineWithFileAndLine) {
    TempDir dir;
    // A raw line break inside a string: nlohmann quotes the whole string read so far.
    const auto path = dir.write("bad.json", "{\n  \"a\": \"" + std::string(5000, 'x') + "\n\"}");
    const std::string what = error_of(path);
    EXPECT_NE(what.find("bad.json:2: "), std::string::npos) << what;
    EXPECT_NE(what.find("last read: '"), std::string::npos) << what;
    EXPECT_NE(what.find("...'"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_LT(what.size(), 400u) << what;
    // The token before "; expected ...", and a token holding "'; expected" itself (fuzzer).
    for (const std::string& key :
         {std::string(3000, '\x7f') + "\xff",
          std::string(3000, '\'') + "'; expected" + std::string(3000, '\'')}) {
        const auto file = dir.write("key.json", "{\n  \"" + key + "\n\": 1}");
        const std::string middle = error_of(file);
        EXPECT_NE(middle.find("key.json:2: "), std::string::npos) << middle;
        EXPECT_NE(middle.find("last read: '"), std::string::npos) << middle;
        EXPECT_EQ(middle.find('\n'), std::string::npos) << middle;
        EXPECT_LT(middle.size(), 400u) << middle;
    }
}

// A key given twice in one object is refused at its line, naming the first; the same key in
// different objects, nested or side by side, is not a repeat.
TEST(ReadJsonFile, AKeyGivenTwiceInOneObjectIsRefusedWithItsLine) {
    TempDir dir;
    EXPECT_EQ(error_of(dir.write("ok.json",
                                 R"({"a": {"a": 1, "b": {"a": 2}}, "b": [{"a": 1}, {"a": 2}]})")),
              "(no error)");
    EXPECT_NE(error_of(dir.write("top.json", "{\"a\": 1,\n\n \"b\": 2, \"a\": 3}"))
                  .find("top.json:3: key 'a' is given twice in one object (first at line 1)"),
              std::string::npos);
    // Inside an array's object, after strings holding braces, quotes and line breaks.
    const std::string text =
        "[{\"x\": \"{\\\"x\\\": }\\n\"},\n {\"y\": 1,\n  \"z\": {\"y\": 2},\n  \"y\": 3}]";
    EXPECT_NE(error_of(dir.write("deep.json", text))
                  .find("deep.json:4: key 'y' is given twice in one object (first at line 2)"),
              std::string::npos)
        << error_of(dir.path() / "deep.json");
    // The parsed value is what nlohmann gives without the check.
    const auto plain =
        dir.write("plain.json", R"({"b": [1, 2.5, "x", null, {"c": true}], "a": {}})");
    EXPECT_EQ(read_json_file(plain), nlohmann::json::parse(read_file(plain)));
}

}  // namespace
}  // namespace hmcr::test
