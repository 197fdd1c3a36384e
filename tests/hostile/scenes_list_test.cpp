// SPDX-License-Identifier: Apache-2.0
// `hmcr scenes` where the data folder is missing or holds no scene, and with scene folders
// whose names hold control characters: a clean refusal, and names printed one a line, escaped.
#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

// `hmcr scenes` with the data folder and the scenes folder given (empty: not set).
CliRun list_scenes(const std::filesystem::path& dir, const std::string& data,
                   const std::string& scenes) {
    return run_launched("env HMCR_DATA_DIR='" + data + "' HMCR_SCENES='" + scenes + "' ", "scenes",
                        dir, 60);
}

TEST_F(Hostile, ScenesWithoutTheirFolderSaySo) {
    const CliRun missing = list_scenes(dir(), (dir() / "nowhere").string(), "");
    EXPECT_EQ(missing.exit_code, 2) << missing.err;
    EXPECT_EQ(missing.out, "");
    EXPECT_EQ(missing.err, "hmcr: error: no bundled scenes: " + (dir() / "nowhere").string() +
                               "/scenes is not a folder (set HMCR_DATA_DIR to hmcr's data "
                               "folder, the one holding scenes/, or HMCR_SCENES to a scenes "
                               "folder)\n");
    m_temp.write("data/scenes/notes.txt", "no scene folder here");
    const CliRun empty = list_scenes(dir(), (dir() / "data").string(), "");
    EXPECT_EQ(empty.exit_code, 2) << empty.err;
    EXPECT_NE(empty.err.find("scenes: holds no bundled scene"), std::string::npos) << empty.err;
    EXPECT_EQ(std::count(empty.err.begin(), empty.err.end(), '\n'), 1) << empty.err;
}

TEST_F(Hostile, SceneNamesAreListedWithTheirControlCharactersEscaped) {
    m_temp.write("sc/a\x1b[2Jb/a\x1b[2Jb.json", "{}");
    m_temp.write("sc/two\nlines/two\nlines.json", "{}");
    m_temp.write("sc/plain/plain.json", "{}");
    const CliRun r = list_scenes(dir(), "", (dir() / "sc").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "a\\x1b[2Jb\nplain\ntwo\\nlines\n");
}

}  // namespace
}  // namespace hmcr::test
