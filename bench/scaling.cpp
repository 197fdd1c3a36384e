// SPDX-License-Identifier: Apache-2.0
#include "bench/scaling.h"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "bench/bench_row.h"
#include "common/atomic_file.h"

extern char** environ;

namespace hmcr::bench {
namespace {

constexpr const char* kOracle = "kl";

struct Point {
    std::string study, scene;
    std::uint64_t rays;
    int threads;
};

// Runs `self --row ...` and returns its JSON row, whose peak memory is the child's own. (The
// kernel's ru_maxrss of a spawned child would count this process's memory too: common/memory.)
nlohmann::json run_point(const std::string& self, const Point& p) {
    const std::string rays = std::to_string(p.rays), threads = std::to_string(p.threads);
    std::vector<std::string> args = {self, "--row", p.scene, kOracle, "nan", rays, threads};
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    if (spawned != 0) throw std::runtime_error("cannot run " + self);
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = read(out[0], buffer, sizeof buffer)) > 0;)
        text.append(buffer, std::size_t(n));
    close(out[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw std::runtime_error(fmt::format("scaling point {} {} failed", p.scene, rays));
    }
    nlohmann::json row = nlohmann::json::parse(text);
    row["study"] = p.study;
    return row;
}

// The exponent b of y ~ x^b through the first and last points.
double growth(const std::vector<nlohmann::json>& rows, const char* x, const char* y) {
    const auto& a = rows.front();
    const auto& b = rows.back();
    return std::log(double(b[y]) / double(a[y])) / std::log(double(b[x]) / double(a[x]));
}

// A series of scripts/plot_study.py's plot data: (x, y) of each row, no error bars.
nlohmann::json series(const std::vector<nlohmann::json>& rows, const std::string& name,
                      const char* x, const std::function<double(const nlohmann::json&)>& y) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& r : rows) {
        points.push_back(
            {{"x", double(r[x])}, {"x_se", nullptr}, {"y", y(r)}, {"y_se", nullptr}, {"n", 1}});
    }
    return {{"name", name}, {"points", points}};
}

nlohmann::json panel(const std::string& title, const std::string& x_label,
                     const std::string& y_label, nlohmann::json series) {
    return {{"type", "lines"},
            {"title", title},
            {"x_label", x_label},
            {"y_label", y_label},
            {"series", series}};
}

}  // namespace

std::vector<nlohmann::json> run_scaling_study(const std::string& self,
                                              const std::filesystem::path& scenes,
                                              const std::filesystem::path& plot_data) {
    std::vector<Point> points;
    for (const char* size : {"100", "1k", "10k", "100k"}) {
        const std::string scene = (scenes / fmt::format("office-{}.obj", size)).string();
        points.push_back({"patches", scene, kBenchRays, 2});
    }
    points.push_back({"patches", "office", kBenchRays, 2});
    for (std::uint64_t rays :
         {std::uint64_t(1'000'000), std::uint64_t(10'000'000), std::uint64_t(100'000'000)}) {
        points.push_back({"rays", "office", rays, 2});
    }
    for (int threads : {1, 2}) {
        points.push_back({"threads", (scenes / "office-100k.obj").string(), kBenchRays, threads});
    }
    fmt::print("\nscaling study: {} on the office, each point in its own process\n", kOracle);
    fmt::print("{:>8} {:>9} {:>10} {:>7} {:>9} {:>8} {:>8} {:>9} {:>9} {:>7} {:>8}\n", "study",
               "patches", "rays", "threads", "leaves", "load s", "setup s", "shoot s", "floor s",
               "x floor", "peak MB");
    std::vector<nlohmann::json> rows;
    for (const Point& p : points) {
        const nlohmann::json r = run_point(self, p);
        fmt::print(
            "{:>8} {:>9} {:>10} {:>7} {:>9} {:>8.2f} {:>8.2f} {:>9.2f} {:>9.3f} {:>7.2f} "
            "{:>8.0f}\n",
            p.study, int(r["patches"]), std::uint64_t(r["rays"]), p.threads, int(r["leaves"]),
            double(r["load_seconds"]), double(r["setup_seconds"]), double(r["seconds"]),
            double(r["floor_seconds"]), double(r["x_floor"]), double(r["peak_bytes"]) / 1e6);
        rows.push_back(r);
    }
    auto of = [&](const std::string& study) {
        std::vector<nlohmann::json> out;
        for (const auto& r : rows) {
            if (r["study"] == study) out.push_back(r);
        }
        return out;
    };
    const auto by_patches = of("patches"), by_rays = of("rays"), by_threads = of("threads");
    fmt::print(
        "growth: rays/s ~ patches^{:.2f}, x floor ~ patches^{:.2f}; shooting s ~ rays^{:.2f}; "
        "peak memory ~ elements^{:.2f} (patches study); 2-thread speed-up {:.2f}\n",
        growth(by_patches, "patches", "rays_per_second"), growth(by_patches, "patches", "x_floor"),
        growth(by_rays, "rays", "seconds"), growth(by_patches, "elements", "peak_bytes"),
        double(by_threads[0]["seconds"]) / double(by_threads[1]["seconds"]));
    auto floor_rate = [](const nlohmann::json& r) {
        return double(r["rays"]) / double(r["floor_seconds"]);
    };
    auto rate = [](const nlohmann::json& r) { return double(r["rays_per_second"]); };
    const auto peak_mb = [](const nlohmann::json& r) { return double(r["peak_bytes"]) / 1e6; };
    const nlohmann::json panels = {
        panel("speed", "patches", "rays per second",
              {series(by_patches, "hmcr kl", "patches", rate),
               series(by_patches, "floor", "patches", floor_rate)}),
        panel("against the floor", "patches", "x floor",
              {series(by_patches, "hmcr kl", "patches",
                      [](const auto& r) { return double(r["x_floor"]); })}),
        panel(
            "rays", "rays", "seconds",
            {series(by_rays, "hmcr kl", "rays", [](const auto& r) { return double(r["seconds"]); }),
             series(by_rays, "floor", "rays",
                    [](const auto& r) { return double(r["floor_seconds"]); })}),
        panel("memory", "leaves", "peak memory (MB)",
              {series(by_patches, "patches study", "leaves", peak_mb),
               series(by_rays, "rays study", "leaves", peak_mb)})};
    const nlohmann::json data = {
        {"figures", {{{"name", "scaling"}, {"columns", 2}, {"panels", panels}}}}};
    write_text_atomically(plot_data, data.dump(2) + "\n");
    fmt::print("scaling plot data: {} (make bench draws it)\n", plot_data.string());
    return rows;
}

}  // namespace hmcr::bench
