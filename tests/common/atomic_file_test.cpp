#include "common/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

TEST(AtomicFile, WritesThroughATempFileAndCreatesParents) {
    TempDir dir;
    const auto target = dir.path() / "a" / "b" / "out.txt";
    std::filesystem::path seen;
    write_file_atomically(target, [&](const std::filesystem::path& tmp) {
        seen = tmp;
        EXPECT_EQ(tmp.parent_path(), target.parent_path());
        EXPECT_NE(tmp, target);
        std::ofstream(tmp) << "new";
        EXPECT_FALSE(std::filesystem::exists(target));  // not visible before the rename
    });
    EXPECT_EQ(read_file(target), "new");
    EXPECT_FALSE(std::filesystem::exists(seen));
    EXPECT_EQ(dir.files(), std::vector<std::string>{"a/b/out.txt"});
}

TEST(AtomicFile, ReplacesExistingFile) {
    TempDir dir;
    const auto target = dir.path() / "out.txt";
    write_text_atomically(target, "old");
    write_text_atomically(target, std::string("n\0ew", 4));
    EXPECT_EQ(read_file(target), std::string("n\0ew", 4));
    EXPECT_EQ(dir.files(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, FailedWriteLeavesOldFileAndNoTemp) {
    TempDir dir;
    const auto target = dir.path() / "out.txt";
    write_text_atomically(target, "old");
    auto failing = [](const std::filesystem::path& tmp) {
        std::ofstream(tmp) << "partial";
        throw std::runtime_error("disk on fire");
    };
    EXPECT_THROW(write_file_atomically(target, failing), std::runtime_error);
    EXPECT_EQ(read_file(target), "old");
    EXPECT_EQ(dir.files(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, ImpossibleTargetThrows) {
    TempDir dir;
    write_text_atomically(dir.path() / "file", "x");
    EXPECT_THROW(write_text_atomically(dir.path() / "file" / "out.txt", "y"), std::runtime_error);
    EXPECT_EQ(dir.files(), std::vector<std::string>{"file"});
}

}  // namespace
}  // namespace hmcr::test
