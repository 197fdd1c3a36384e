// SPDX-License-Identifier: Apache-2.0
#include "common/error.h"

#include <gtest/gtest.h>

namespace hmcr {
namespace {

TEST(InputError, ALongPlaceIsCutInTheMiddleKeepingFileAndLine) {
    const std::string place = std::string(1000, 'd') + "/scene.obj:12";
    const std::string what = InputError(place, "bad").what();
    EXPECT_EQ(what,
              std::string(100, 'd') + "..." + std::string(200 - 13, 'd') + "/scene.obj:12: bad");
    EXPECT_EQ(std::string(InputError("a/b.obj:3", "bad").what()), "a/b.obj:3: bad");
}

TEST(InputError, ControlCharactersAreEscapedSoTheMessageIsOneLine) {
    EXPECT_EQ(one_line("plain text: 'a b'"), "plain text: 'a b'");
    EXPECT_EQ(one_line("a\nb\rc\td"), "a\\nb\\rc\\td");
    EXPECT_EQ(one_line(std::string("x\x1b[2J\x7f", 6) + std::string(1, '\0')),
              "x\\x1b[2J\\x7f\\x00");
    EXPECT_EQ(one_line("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 passes as it is
    const InputError e("scene.json", "unknown key 'a\nb'");
    EXPECT_STREQ(e.what(), "scene.json: unknown key 'a\\nb'");
    EXPECT_STREQ(InputError("two\nlines").what(), "two\\nlines");
}

}  // namespace
}  // namespace hmcr
