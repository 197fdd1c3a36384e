// SPDX-License-Identifier: Apache-2.0
#include "app/plot_script.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "common/data_directory.h"
#include "common/error.h"
#include "common/interrupt.h"

extern char** environ;

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// What becomes of a child's stderr.
enum class Stderr { silent, last_line };

// The last line of what arrives on `fd` until its end: only the last 4 KiB are kept, so a
// script that writes gigabytes costs no memory.
std::string last_line_of(int fd) {
    constexpr std::size_t kKeep = 4096;
    std::string tail;
    char buffer[4096];
    for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        tail.append(buffer, std::size_t(n));
        if (tail.size() > 2 * kKeep) tail.erase(0, tail.size() - kKeep);
    }
    while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back()))) tail.pop_back();
    const std::size_t start = tail.find_last_of('\n');
    return start == std::string::npos ? tail : tail.substr(start + 1);
}

// Runs argv[0] (searched on the PATH) and waits for it: its exit status, or -1 when it could
// not be started or did not exit. With Stderr::last_line, *last is the last line it wrote
// there. Silent, its output goes to /dev/null.
int run(std::vector<std::string> args, Stderr err, std::string* last = nullptr) {
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int pipe_fds[2] = {-1, -1};
    if (err == Stderr::last_line && pipe2(pipe_fds, O_CLOEXEC) != 0) return -1;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (err == Stderr::silent) {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    } else if (err == Stderr::last_line) {
        posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    }
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err == Stderr::last_line) {
        close(pipe_fds[1]);
        if (spawned == 0 && last) *last = last_line_of(pipe_fds[0]);
        close(pipe_fds[0]);
    }
    if (spawned != 0) return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) return -1;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

constexpr const char* kFindsMatplotlib =
    "import importlib.util, sys; sys.exit(importlib.util.find_spec('matplotlib') is None)";

std::vector<std::string> candidates() {
    const char* chosen = std::getenv(kPythonVariable);
    if (chosen != nullptr && *chosen != '\0') return {chosen};
    return {"python3", "/usr/bin/python3"};
}

}  // namespace

std::optional<std::string> plotting_python() {
    for (const std::string& python : candidates()) {
        // Found, not imported: an import takes a third of a second, the search a few ms.
        if (run({python, "-c", kFindsMatplotlib}, Stderr::silent) == 0) return python;
    }
    return std::nullopt;
}

fs::path plot_script() { return data_directory() / "scripts" / "plot_study.py"; }

std::string why_no_plots(const std::optional<std::string>& python, const fs::path& study) {
    const std::string then = fmt::format("then `hmcr plot {}`", study.string());
    if (!python) {
        const char* chosen = std::getenv(kPythonVariable);
        const std::string tried = chosen != nullptr && *chosen != '\0'
                                      ? fmt::format("${} ({})", kPythonVariable, chosen)
                                      : std::string("python3, /usr/bin/python3");
        return fmt::format(
            "no Python with matplotlib ({}): install it (Debian: "
            "python3-matplotlib), {}",
            tried, then);
    }
    std::error_code ec;
    if (!fs::is_regular_file(plot_script(), ec)) {
        return fmt::format(
            "no plotting script {}: set {} to the folder holding scripts/ and "
            "scenes/ (an install's share/hmcr), {}",
            plot_script().string(), kDataDirVariable, then);
    }
    return "";
}

void draw_plots(const std::string& python, const fs::path& data) {
    std::string said;
    const int status =
        run({python, plot_script().string(), data.string()}, Stderr::last_line, &said);
    throw_if_interrupted();
    if (status != 0) {
        const std::string why = said.empty() ? "" : ": " + one_line(said).substr(0, 300);
        throw InputError(fmt::format("the plotting script {} failed on {} (exit {}{})",
                                     plot_script().string(), data.string(), status, why));
    }
}

void draw_study_plots(const fs::path& study, bool quiet) {
    const std::optional<std::string> python = plotting_python();
    if (const std::string why = why_no_plots(python, study); !why.empty()) {
        if (!quiet) fmt::print(stderr, "hmcr: warning: plots not drawn: {}\n", why);
        return;
    }
    // The study's results are whole: a script that fails costs its plots, not the study.
    try {
        draw_plots(*python, study / "plots" / "plot_data.json");
    } catch (const Interrupted&) {
        throw;
    } catch (const std::runtime_error& e) {
        fmt::print(stderr, "hmcr: warning: plots not drawn: {}; draw them with `hmcr plot {}`\n",
                   e.what(), study.string());
    }
}

}  // namespace hmcr
