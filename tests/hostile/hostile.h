// SPDX-License-Identifier: Apache-2.0
// The hostile-input suite: every case runs the hmcr binary as a careless or hostile user would
// and checks the promise of docs/usage.md#bad-input: exit code 2, one line on stderr naming what
// and where, no hang, and not one file of the working folder written, removed or changed.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/fs.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

#include "tests/support/cli_run.h"

namespace hmcr::test {

// The plates scene (two unit squares, an emitter and a grey receiver), as text to spoil.
inline const char* kPlatesObj =
    "mtllib plates.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "usemtl emitter\nf 1 2 3 4\n"
    "usemtl receiver\nf 5 8 7 6\n";
inline const char* kPlatesMtl =
    "newmtl emitter\nKd 0 0 0\nKe 0.3 0.3 0.3\n"
    "newmtl receiver\nKd 0.5 0.5 0.5\nKe 0 0 0\n";
inline const char* kPlatesJson =
    R"({"mesh": "plates.obj", "views": [{"name": "side", "position": [2.8, 0.5, 0.5],
        "look_at": [0.5, 0.5, 0.5], "width": 32, "height": 32}]})";

// Starts hmcr ARGS in `dir` (its output in .stdout and .stderr there), sends `signal` after
// `delay`, returns the exit status.
inline int interrupted(const std::string& args, const std::filesystem::path& dir, int signal,
                       std::chrono::milliseconds delay) {
    const pid_t child = fork();
    if (child == 0) {
        const std::string cmd =
            "cd '" + dir.string() + "' && exec " + HMCR_BINARY + " " + args + " >.stdout 2>.stderr";
        execl("/bin/sh", "sh", "-c", cmd.c_str(), nullptr);
        _exit(127);
    }
    std::this_thread::sleep_for(delay);
    kill(child, signal);
    int status = 0;
    waitpid(child, &status, 0);
    return status;
}

// A folder no file can be made in while this lives: read-only for a user, immutable for root
// (whom file modes do not stop). ok() is false where neither can be had (a file system without
// the immutable flag).
class Unwritable {
public:
    explicit Unwritable(const std::filesystem::path& folder) : m_folder(folder) {
        if (::geteuid() != 0) {
            m_ok = ::chmod(folder.c_str(), 0555) == 0;
            return;
        }
        m_ok = set_immutable(true);
    }
    ~Unwritable() {
        if (!m_ok) return;
        if (::geteuid() != 0) {
            ::chmod(m_folder.c_str(), 0755);
        } else {
            set_immutable(false);
        }
    }
    Unwritable(const Unwritable&) = delete;
    Unwritable& operator=(const Unwritable&) = delete;
    bool ok() const { return m_ok; }

private:
    bool set_immutable(bool on) const {
        const int fd = ::open(m_folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd < 0) return false;
        int flags = 0;
        bool done = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
        flags = on ? flags | FS_IMMUTABLE_FL : flags & ~FS_IMMUTABLE_FL;
        done = done && ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
        ::close(fd);
        return done;
    }

    std::filesystem::path m_folder;
    bool m_ok = false;
};

class Hostile : public testing::Test {
protected:
    // Writes the plates scene (with the given texts) into the working folder.
    void plates(const std::string& obj = kPlatesObj, const std::string& mtl = kPlatesMtl,
                const std::string& json = kPlatesJson) const {
        m_temp.write("plates.obj", obj);
        m_temp.write("plates.mtl", mtl);
        m_temp.write("plates.json", json);
    }

    // Runs hmcr ARGS in the working folder and expects a clean refusal mentioning `needle`.
    CliRun refused(const std::string& args, const std::string& needle) const {
        const auto before = snapshot(dir());
        const CliRun r = run_hmcr(args, dir());
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
        EXPECT_LT(r.err.size(), 400u) << args;
        EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
        EXPECT_EQ(r.err.find("vtk"), std::string::npos) << r.err;  // in hmcr's words
        EXPECT_TRUE(snapshot(dir()) == before) << args << ": the folder changed";
        return r;
    }

    // Runs hmcr ARGS and expects success.
    CliRun accepted(const std::string& args) const {
        const CliRun r = run_hmcr(args, dir());
        EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
        return r;
    }

    const std::filesystem::path& dir() const { return m_temp.path(); }

    TempDir m_temp;
};

// `text` with the first `from` replaced by `to`: a valid input spoiled in one place.
inline std::string with(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

}  // namespace hmcr::test
