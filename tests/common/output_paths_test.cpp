// SPDX-License-Identifier: Apache-2.0
#include "common/output_paths.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/error.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
    try {
        refuse_overwriting(outputs, inputs);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// The same file by any spelling, link or hard link is one file; two files are two.
TEST(RefuseOverwriting, FindsAnInputOrARepeatByAnyPath) {
    TempDir dir;
    const fs::path scene = dir.write("scene.json", "{}");
    fs::create_hard_link(scene, dir.path() / "hard.json");
    fs::create_symlink(scene, dir.path() / "soft.json");
    fs::create_directories(dir.path() / "sub");
    for (const fs::path& same : {dir.path() / "sub" / ".." / "scene.json", dir.path() / "hard.json",
                                 dir.path() / "soft.json"}) {
        EXPECT_NE(
            refusal({dir.path() / "x.vtp", same}, {scene}).find("is an input of this command"),
            std::string::npos)
            << same;
    }
    const fs::path x = dir.path() / "x.vtp";
    EXPECT_NE(refusal({x, dir.path() / "y.vtp", dir.path() / "sub" / ".." / "x.vtp"}, {scene})
                  .find("is named for two outputs"),
              std::string::npos);
    EXPECT_EQ(refusal({x, dir.path() / "y.vtp", dir.path() / "sub" / "x.vtp"}, {scene}), "");
}

// The count of work: one identity per path, not one per pair (a sampling study of 1,000 spp
// values has over 2,000 outputs: its pairs took 75 s before its first cell).
TEST(RefuseOverwriting, FindsEachPathsIdentityOnce) {
    TempDir dir;
    std::vector<fs::path> outputs, inputs{dir.write("a.obj", ""), dir.write("a.mtl", "")};
    for (int i = 0; i < 5000; ++i) {
        outputs.push_back(dir.path() / "figures" / ("v-spp" + std::to_string(i) + ".png"));
    }
    const std::uint64_t before = file_identities_computed();
    refuse_overwriting(outputs, inputs);
    EXPECT_EQ(file_identities_computed() - before, outputs.size() + inputs.size());
}

}  // namespace
}  // namespace hmcr::test
