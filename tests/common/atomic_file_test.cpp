// SPDX-License-Identifier: Apache-2.0
#include "common/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <thread>

#include "common/durable_file.h"
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

// Ranks of an MPI run on different nodes may have the same process id: a name made of the pid
// and a count collides with a temporary file of another node's writer in a shared folder.
TEST(AtomicFile, AnotherWritersTemporaryFileIsNoObstacle) {
    TempDir dir;
    const auto target = dir.path() / "cell.json";
    for (int n = 0; n < 256; ++n) {
        const std::string pid = std::to_string(::getpid());
        dir.write("cell.json.tmp." + pid + "." + std::to_string(n), "theirs");
    }
    write_text_atomically(target, "mine");
    EXPECT_EQ(read_file(target), "mine");
    EXPECT_EQ(dir.files().size(), 257u);
}

TEST(AtomicFile, ConcurrentWritersOfOneTargetEachWriteWhole) {
    TempDir dir;
    const auto target = dir.path() / "out.txt";
    std::vector<std::thread> writers;
    for (int w = 0; w < 4; ++w) {
        writers.emplace_back([&, w] {
            const std::string text(1000, char('a' + w));
            for (int k = 0; k < 50; ++k) write_text_atomically(target, text);
        });
    }
    for (std::thread& t : writers) t.join();
    const std::string text = read_file(target);
    ASSERT_EQ(text.size(), 1000u);
    EXPECT_EQ(text, std::string(1000, text[0]));  // one writer's, not a mix
    EXPECT_EQ(dir.files(), std::vector<std::string>{"out.txt"});
}

// What a flush saw: the file's path (through /proc) and whether the target existed yet.
struct Flush {
    std::string path;
    bool target_there;
};
std::vector<Flush> g_flushes;
std::filesystem::path g_target;

int recording_fsync(int fd) {
    std::error_code ec;
    const auto path = std::filesystem::read_symlink("/proc/self/fd/" + std::to_string(fd), ec);
    g_flushes.push_back({path.string(), std::filesystem::exists(g_target)});
    return ::fsync(fd);
}

// A crash of the machine after the rename must not leave an empty target: the bytes are flushed
// before the rename, the folder's new entry after it.
TEST(AtomicFile, FlushesTheBytesBeforeTheRenameAndTheFolderAfter) {
    TempDir dir;
    g_target = std::filesystem::canonical(dir.path()) / "out.txt";
    g_flushes.clear();
    const SyncCall system_call = replace_sync_call(&recording_fsync);
    write_text_atomically(g_target, "bytes");
    replace_sync_call(system_call);
    ASSERT_EQ(g_flushes.size(), 2u);
    EXPECT_EQ(std::filesystem::path(g_flushes[0].path).parent_path(), g_target.parent_path());
    EXPECT_NE(g_flushes[0].path, g_target.string());                // the temporary file, ...
    EXPECT_FALSE(g_flushes[0].target_there);                        // ... before the rename
    EXPECT_EQ(g_flushes[1].path, g_target.parent_path().string());  // the folder, ...
    EXPECT_TRUE(g_flushes[1].target_there);                         // ... after it
}

TEST(AtomicFile, TemporaryNamesAreHiddenAndWithinTheNameLimit) {
    TempDir dir;
    const std::string long_name(255, 'n');
    std::filesystem::path seen;
    write_file_atomically(dir.path() / long_name, [&](const std::filesystem::path& tmp) {
        seen = tmp;
        std::ofstream(tmp) << "x";
    });
    EXPECT_EQ(seen.filename().string().front(), '.');
    EXPECT_LE(seen.filename().string().size(), 255u);
    EXPECT_EQ(read_file(dir.path() / long_name), "x");
}

}  // namespace
}  // namespace hmcr::test
