// SPDX-License-Identifier: Apache-2.0
#include "common/output_set.h"

#include <gtest/gtest.h>

#include "common/atomic_file.h"
#include "common/error.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

TEST(OutputSet, CommitPutsEveryFileInPlaceAtOnce) {
    TempDir dir;
    const fs::path a = dir.path() / "new" / "x.vtp", b = dir.path() / "new" / "x.json";
    OutputSet out({a, b});
    write_text_atomically(out.temp(a), "vtp");
    write_text_atomically(out.temp(b), "json");
    EXPECT_FALSE(fs::exists(a));  // nothing visible before the commit
    out.commit();
    EXPECT_EQ(read_file(a), "vtp");
    EXPECT_EQ(read_file(b), "json");
    EXPECT_EQ(dir.files(), (std::vector<std::string>{"new/x.json", "new/x.vtp"}));
}

TEST(OutputSet, WithoutCommitNothingIsLeft) {
    TempDir dir;
    const fs::path a = dir.path() / "d" / "e" / "x.vtp", b = dir.path() / "d" / "x.json";
    {
        OutputSet out({a, b});
        write_text_atomically(out.temp(a), "vtp");
    }
    EXPECT_TRUE(fs::is_empty(dir.path()));  // not even the folders it made
}

// A run killed outright (SIGKILL) during its work leaves at most its lock files: the temporary
// files are made at the end, when the command writes them.
TEST(OutputSet, TemporaryFilesAreMadeOnlyWhenWritten) {
    TempDir dir;
    const fs::path a = dir.path() / "x.vtp";
    OutputSet out({a});
    EXPECT_EQ(dir.files(), std::vector<std::string>{".x.vtp.lock"});
    EXPECT_THROW(out.commit(), std::logic_error);  // x.vtp was never written
}

TEST(OutputSet, OldFilesStayUntilTheCommit) {
    TempDir dir;
    const fs::path a = dir.write("x.vtp", "old");
    {
        OutputSet out({a});
        write_text_atomically(out.temp(a), "new");
    }
    EXPECT_EQ(read_file(a), "old");
    EXPECT_EQ(dir.files(), std::vector<std::string>{"x.vtp"});
}

TEST(OutputSet, EveryFileIsCheckedBeforeAnyIsTouched) {
    TempDir dir;
    fs::create_directories(dir.path() / "x.json");
    const fs::path vtp = dir.path() / "sub" / "x.vtp";
    EXPECT_THROW(OutputSet({vtp, dir.path() / "x.json"}), InputError);
    EXPECT_THROW(OutputSet({dir.path() / std::string(256, 'y')}), InputError);
    EXPECT_THROW(OutputSet({dir.path() / "x.json" / ".."}), InputError);
    EXPECT_THROW(OutputSet({"/dev/null"}), InputError);
    EXPECT_FALSE(fs::exists(dir.path() / "sub"));
    EXPECT_TRUE(fs::is_empty(dir.path() / "x.json"));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 1);
}

TEST(OutputSet, ASecondSetOfTheSameFileIsRefusedWhileTheFirstIsOpen) {
    TempDir dir;
    const fs::path a = dir.path() / "x.vtp";
    {
        OutputSet first({a});
        try {
            OutputSet second({dir.path() / "y.vtp", a});
            ADD_FAILURE() << "a second set of x.vtp was opened";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("another hmcr run is writing it"),
                      std::string::npos)
                << e.what();
        }
        OutputSet other({dir.path() / "y.vtp"});  // another file is free
        write_text_atomically(first.temp(a), "first");
        first.commit();
        OutputSet after({a});  // committed: free again
    }
    EXPECT_EQ(dir.files(), std::vector<std::string>{"x.vtp"});  // no lock file left
}

TEST(OutputSet, AFolderIsLockedAsOne) {
    TempDir dir;
    const fs::path ref = dir.path() / "ref";
    OutputSet first({ref / "reference.json"}, ref);
    EXPECT_THROW(OutputSet({ref / "views" / "v.png"}, ref), InputError);
    EXPECT_FALSE(fs::exists(ref / "views"));
}

TEST(OutputSet, ALockLeftByAKilledRunIsTakenOver) {
    TempDir dir;
    dir.write(".x.vtp.lock", "");  // its process is gone, and its flock with it
    OutputSet out({dir.path() / "x.vtp"});
    write_text_atomically(out.temp(dir.path() / "x.vtp"), "x");
    out.commit();
    EXPECT_EQ(dir.files(), std::vector<std::string>{"x.vtp"});
}

// A study cell's files: all into place at the commit, or none (nor the folders made for them).
TEST(FileBatch, PutsItsFilesInPlaceTogetherOrLeavesNone) {
    TempDir dir;
    dir.write("cells/old.json", "kept");
    const fs::path image = dir.path() / "images" / "c-side.png",
                   cell = dir.path() / "cells" / "c.json";
    {
        FileBatch files;
        write_text_atomically(files.temp(image), "png");
        EXPECT_EQ(files.temp(image), files.temp(image));  // one temporary file per file
        write_text_atomically(files.temp(cell), "json");
    }  // abandoned: a signal during the cell
    EXPECT_EQ(dir.files(), std::vector<std::string>{"cells/old.json"});
    EXPECT_FALSE(fs::exists(dir.path() / "images"));
    FileBatch files;
    write_text_atomically(files.temp(image), "png");
    write_text_atomically(files.temp(cell), "json");
    EXPECT_FALSE(fs::exists(image));
    files.commit();
    EXPECT_EQ(read_file(image), "png");
    EXPECT_EQ(dir.files(),
              (std::vector<std::string>{"cells/c.json", "cells/old.json", "images/c-side.png"}));
}

}  // namespace
}  // namespace hmcr::test
