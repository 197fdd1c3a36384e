// SPDX-License-Identifier: Apache-2.0
#include "common/file_names.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace hmcr::test {
namespace {

TEST(FileNames, PortableNamesPass) {
    for (const char* name : {"camera", "side-2", "top_view", "v1.5", "spp1e+06", "A"}) {
        EXPECT_FALSE(name_problem(name)) << name;
    }
    EXPECT_FALSE(name_problem(std::string(kMaxNameBytes, 'v')));
}

TEST(FileNames, NamesThatCouldLeaveTheirFolderOrBreakALineAreRefused) {
    const std::vector<std::string> names = {"",
                                            "..",
                                            ".",
                                            "../../ESCAPED",
                                            "/tmp/x",
                                            "a/b",
                                            "a\\b",
                                            "a\nb",
                                            ".hidden",
                                            "-rf",
                                            "two words",
                                            "caf\xc3\xa9",
                                            std::string("nul\0byte", 8),
                                            std::string(kMaxNameBytes + 1, 'v')};
    for (const std::string& name : names) {
        EXPECT_TRUE(name_problem(name)) << name;
        EXPECT_THROW(check_name(name, "view name"), InputError) << name;
    }
}

TEST(FileNames, NamedFileStaysInItsFolder) {
    EXPECT_EQ(named_file("out/views", "side", ".pfm"), std::filesystem::path("out/views/side.pfm"));
    EXPECT_THROW(named_file("out/views", "../../x", ".pfm"), InputError);
    EXPECT_THROW(named_file("out", "", ""), InputError);
    EXPECT_THROW(named_file("out", std::string(252, 'c'), ".json"), InputError);  // > 255 bytes
    EXPECT_NO_THROW(named_file("out", std::string(250, 'c'), ".json"));
    EXPECT_THROW(named_file("out", ".", "."), InputError);
    EXPECT_THROW(named_file("out", "a\nb", ".png"), InputError);
    // A scene file's own name may hold what a view's may not: it is a file name already.
    EXPECT_EQ(named_file("out", "my scene", ".vtp"), std::filesystem::path("out/my scene.vtp"));
}

TEST(FileNames, TheReasonNamesTheCharacter) {
    try {
        check_name("a\nb", "view name");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "view name 'a\\nb' cannot name a file: '\\n' is not a letter, "
                     "digit, '.', '_', '-' or '+'");
    }
}

}  // namespace
}  // namespace hmcr::test
