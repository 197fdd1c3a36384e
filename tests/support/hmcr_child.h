// SPDX-License-Identifier: Apache-2.0
// The hmcr binary as a child process of the test, measured: how long it ran, how long it took to
// end after a signal, and its peak resident memory. run_hmcr (cli_run.h) goes through a shell,
// whose own memory and time would be measured with it; this one is hmcr alone.
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"

namespace hmcr::test {

struct ChildExit {
    int code = -1;       // the exit code, or 128 + the signal that ended it
    double seconds = 0;  // from the start, or from the last signal() if one was sent
    // wait4's ru_maxrss: hmcr's own peak, or the resident size of this test process when it
    // forked if that was larger (tens of MB: the test process is small)
    std::uint64_t peak_bytes = 0;
    std::string err;  // what it wrote on stderr
};

class HmcrChild {
public:
    // Starts `hmcr ARGS` (split at spaces, no quoting) in `dir`, killed by SIGALRM after
    // `seconds`; stdout and stderr go to .stdout and .stderr there, removed by wait().
    HmcrChild(const std::string& args, const std::filesystem::path& dir, unsigned seconds)
        : m_dir(dir), m_start(std::chrono::steady_clock::now()) {
        std::vector<std::string> words{HMCR_BINARY};
        std::istringstream split(args);
        for (std::string w; split >> w;) words.push_back(w);
        m_pid = fork();
        if (m_pid == 0) {
            std::vector<char*> argv;
            for (std::string& w : words) argv.push_back(w.data());
            argv.push_back(nullptr);
            if (chdir(dir.c_str()) != 0 || !freopen(".stdout", "w", stdout) ||
                !freopen(".stderr", "w", stderr)) {
                _exit(127);
            }
            alarm(seconds);  // survives the exec: the child's time limit
            execv(argv[0], argv.data());
            _exit(127);
        }
    }
    HmcrChild(const HmcrChild&) = delete;
    HmcrChild& operator=(const HmcrChild&) = delete;
    ~HmcrChild() {
        if (m_pid > 0) {
            kill(m_pid, SIGKILL);
            waitpid(m_pid, nullptr, 0);
        }
    }

    // Sends the signal and restarts the clock: wait() then says how long hmcr took to end.
    void signal(int sig) {
        m_start = std::chrono::steady_clock::now();
        kill(m_pid, sig);
    }

    ChildExit wait() {
        int status = 0;
        rusage usage{};
        wait4(m_pid, &status, 0, &usage);
        m_pid = -1;
        ChildExit e;
        e.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        e.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        e.peak_bytes = std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
        e.err = read_file(m_dir / ".stderr");
        std::filesystem::remove(m_dir / ".stdout");
        std::filesystem::remove(m_dir / ".stderr");
        return e;
    }

private:
    std::filesystem::path m_dir;
    std::chrono::steady_clock::time_point m_start;
    pid_t m_pid = -1;
};

}  // namespace hmcr::test
