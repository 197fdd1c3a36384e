// SPDX-License-Identifier: Apache-2.0
// `hmcr info SCENE|SOLUTION.vtp`: the information measures of a discretisation (docs/design.md §7);
// `hmcr info --bounds SCENE`: what a view needs, the scene's bounding box, up axis and emitters.
#include <fmt/core.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "app/command.h"
#include "app/count.h"
#include "app/scene_input.h"
#include "app/terminal_progress.h"
#include "common/stopwatch.h"
#include "information/back_sides.h"
#include "information/scene_information.h"
#include "meshes/scene.h"
#include "meshes/scene_bounds.h"
#include "viz/solution_file.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

struct InfoArgs {
    std::string scene;             // a scene, or a solution's .vtp
    std::string solution_scene;    // with a .vtp: the scene's name, for the report
    std::string method = "local";  // local or global lines
    std::uint64_t lines = 1'000'000;
    std::uint64_t seed = 1;
    bool json = false;
    bool bounds = false;  // print the scene's bounds instead of measuring it
    SceneFlags scene_flags;
};

// The discretisation `hmcr info` measures: a scene's patches, or a solution file's cells, by
// side. The cells are the solution's leaves but for its clusters (a leaf of several cells, which
// share its radiosity), whose cells are measured each apart.
struct InfoTarget {
    std::string label;
    ChannelStates states;
    const char* noun = "patches";  // what a state is: patches, or a solution's leaves or cells
    std::size_t leaves = 0;        // of a clustered solution: its leaves, clusters among them
    std::size_t clusters = 0;
};

// A solution's leaves: each cell side outside the clusters, and each cluster (a leaf of several
// cells, which share its radiosity); and how many are clusters.
std::pair<std::size_t, std::size_t> leaves_and_clusters(const ShadedMesh& mesh) {
    std::set<std::int32_t> clusters;
    std::size_t unclustered = 0;
    // A leaf of a higher-order solution is several cells, all of one side: counted once.
    for (std::size_t c = 0; c < mesh.cluster_id.size(); ++c) {
        const std::int32_t id = mesh.cluster_id[c];
        if (id >= 0) {
            clusters.insert(id);
        } else if (mesh.leaf_index.empty() || c == 0 ||
                   mesh.leaf_index[c] != mesh.leaf_index[c - 1]) {
            ++unclustered;
        }
    }
    if (mesh.cluster_id.empty()) unclustered = mesh.leaf_count();
    return {unclustered + clusters.size(), clusters.size()};
}

InfoTarget info_target(const InfoArgs& a) {
    if (fs::path(a.scene).extension() != ".vtp") {
        const Scene scene = load_scene_reporting(a.scene, false, SceneUse::geometry, a.scene_flags);
        return {scene.name, patch_states(build_patch_set(scene.mesh))};
    }
    // With --scene the solution must be of that scene; without, it names its own.
    const SolutionFile solution =
        a.solution_scene.empty()
            ? read_solution(a.scene)
            : read_solution(a.scene, load_scene_reporting(a.solution_scene, false,
                                                          SceneUse::geometry, a.scene_flags));
    const std::string file = fs::path(a.scene).filename().string();
    const auto [leaves, clusters] = leaves_and_clusters(solution.mesh);
    if (clusters == 0) {
        return {solution.meta.scene + " (leaves of " + file + ")", leaf_states(solution.mesh),
                "leaves"};
    }
    return {fmt::format("{} (cells of {}, not its {} leaves: {} of them clusters, whose cells are "
                        "measured each apart)",
                        solution.meta.scene, file, leaves, clusters),
            leaf_states(solution.mesh), "cells", leaves, clusters};
}

// "N patches" (or cells), and with backs "N patches and M backs (S sides)": the channel's
// states.
std::string state_count(const InfoTarget& t) {
    const std::size_t fronts = t.states.fronts(), sides = t.states.states.patches.size();
    if (sides == fronts) return fmt::format("{} {}", fronts, t.noun);
    return fmt::format("{} {} and {} backs ({} sides)", fronts, t.noun, sides - fronts, sides);
}

void print_table(const InfoTarget& t, const InformationMeasures& m, double seconds) {
    fmt::print(
        "{}: {}, {} {} lines, {} rays ({} open), {:.1f} s; bits, +- one standard "
        "error, bias to subtract (1/n extrapolation)\n",
        t.label, state_count(t), m.lines, line_method_name(m.method), m.samples, m.samples_open,
        seconds);
    const std::pair<const char*, InformationMeasures::Value> rows[] = {
        {"H_P   positional entropy", m.h_p},
        {"H_S   visibility entropy", m.h_s},
        {"I_S   mutual information", m.i_s},
        {"H_J   joint entropy", m.h_j},
        {"I^c_S continuous mutual information", m.i_cs},
        {"I^c_S - I_S discretisation error", m.discretisation_error}};
    for (const auto& [name, v] : rows) {
        fmt::print("  {:<38} {:10.5f} +- {:.5f}   bias {:+.5f}\n", name, v.estimate,
                   v.standard_error, v.bias);
    }
}

void print_json(const InfoTarget& t, const InformationMeasures& m, double open, double seconds) {
    nlohmann::json j = to_json(m);
    j["open_fraction"] = open;
    j["scene"] = t.label;
    j["patches"] = t.states.fronts();  // the front states, patches or cells
    j["states"] = t.noun;
    if (t.clusters > 0) {
        j["leaves"] = t.leaves;
        j["clusters"] = t.clusters;
    }
    if (t.states.backs) j["backs"] = t.states.states.patches.size() - t.states.fronts();
    j["seconds"] = seconds;
    fmt::print("{}\n", j.dump(2));
}

// The measures describe a closed scene's channel, with every row of F sampled.
void warn_assumptions(const InformationMeasures& m, double open, const InfoTarget& t) {
    const std::size_t states = t.states.states.patches.size();
    const char* noun = t.states.backs ? "sides" : t.noun;
    if (open > 0.01) {
        fmt::print(
            stderr,
            "hmcr: warning: {:.1f}% of the rays leave the scene or hit a one-sided back; the "
            "measures assume a closed scene (rows of F summing to 1)\n",
            100 * open);
    }
    if (std::abs(m.i_s.bias) > m.i_s.standard_error) {
        fmt::print(stderr,
                   "hmcr: warning: I_S has not converged: its plug-in bias (about {:+.4f} bits, "
                   "likely more) exceeds its standard error; raise --lines\n",
                   m.i_s.bias);
    }
    if (m.patches_unsampled > 0) {
        fmt::print(stderr,
                   "hmcr: warning: no line crossed {} of the {} {}; their rows of F are "
                   "missing (use more lines)\n",
                   m.patches_unsampled, states, noun);
    }
}

// A bar only on a terminal: the output (a table or JSON) goes to stdout and warnings to stderr,
// where a log of percentages would bury the warnings.
InformationMeasures measure(const InfoTarget& target, const LineOptions& o) {
    const bool terminal = progress_mode_for("auto", false) == ProgressMode::bar;
    TerminalProgress progress(terminal ? ProgressMode::bar : ProgressMode::none, "hmcr info");
    progress.stage(fmt::format("{} lines", line_method_name(o.method)));
    return scene_information(target.states, o, progress);
}

std::string point_text(const Eigen::Vector3d& p) {
    return fmt::format("({:.4g}, {:.4g}, {:.4g})", p.x(), p.y(), p.z());
}

nlohmann::json point_json(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

std::string view_text(const View& v) {
    return fmt::format("{}: from {} towards {}, up {}, {:g} degrees, {} x {}", v.name,
                       point_text(v.position), point_text(v.look_at), point_text(v.up),
                       v.fov_degrees, v.width, v.height);
}

nlohmann::json view_json(const View& v) {
    return {{"name", v.name},
            {"position", point_json(v.position)},
            {"look_at", point_json(v.look_at)},
            {"up", point_json(v.up)},
            {"fov", v.fov_degrees},
            {"width", v.width},
            {"height", v.height}};
}

// The scene's bounding box, up axis guess, patches, emitters and views: what writing a view takes.
int run_bounds(const InfoArgs& a) {
    if (fs::path(a.scene).extension() == ".vtp") {
        throw InputError("--bounds takes a scene, not a solution: " + quote(a.scene));
    }
    const Scene scene = load_scene_reporting(a.scene, false, SceneUse::geometry, a.scene_flags);
    const SceneBounds b = scene_bounds(scene.mesh);
    const bool own_views = !scene.default_views;
    if (a.json) {
        nlohmann::json views = nlohmann::json::array();
        for (const View& v : scene.views) views.push_back(view_json(v));
        const nlohmann::json j = {{"scene", scene.name},
                                  {"lo", point_json(b.lo)},
                                  {"hi", point_json(b.hi)},
                                  {"up", axis_name(b.up)},
                                  {"up_reason", b.up_reason},
                                  {"patches", b.patches},
                                  {"two_sided", b.two_sided},
                                  {"emitters", b.emitters},
                                  {"emitting_area", b.emitting_area},
                                  {"emitted_power", point_json(b.emitted_power)},
                                  {"views", views},
                                  {"default_view", !own_views}};
        fmt::print("{}\n", j.dump(2));
        return 0;
    }
    const Eigen::Vector3d size = b.hi - b.lo;
    fmt::print("{}: bounding box {} to {}, {:.4g} x {:.4g} x {:.4g} m\n", scene.name,
               point_text(b.lo), point_text(b.hi), size.x(), size.y(), size.z());
    fmt::print("up: {} ({})\n", axis_name(b.up), b.up_reason);
    fmt::print("patches: {} ({} two-sided)\n", b.patches, b.two_sided);
    fmt::print("emitters: {} patches, {:.4g} m^2, power {} W\n", b.emitters, b.emitting_area,
               point_text(b.emitted_power));
    if (!own_views) {
        fmt::print("views: none of its own; the default view, {} the scene:\n  {}\n",
                   default_view(scene.mesh, b).inside ? "inside" : "outside",
                   view_text(scene.views[0]));
        return 0;
    }
    fmt::print("views:\n");
    for (const View& v : scene.views) fmt::print("  {}\n", view_text(v));
    return 0;
}

int run_info(const InfoArgs& a) {
    if (a.bounds) return run_bounds(a);
    LineOptions o;
    o.method = parse_line_method(a.method);
    o.lines = a.lines;
    o.seed = a.seed;
    if (a.lines < 16) throw InputError("lines must be at least 16");
    const InfoTarget target = info_target(a);
    const auto start = std::chrono::steady_clock::now();
    const InformationMeasures m = measure(target, o);
    const double seconds = seconds_since(start);
    const double open = double(m.samples_open) / double(std::max<std::size_t>(1, m.samples));
    if (a.json) {
        print_json(target, m, open, seconds);
    } else {
        print_table(target, m, seconds);
    }
    warn_assumptions(m, open, target);
    return 0;
}

}  // namespace

Command info_command(CLI::App& app) {
    auto a = std::make_shared<InfoArgs>();
    auto* cmd = app.add_subcommand(
        "info", "information measures of a scene's patches (entropies, mutual information)");
    cmd->add_option("scene", a->scene,
                    "bundled scene name, scene .json, mesh (.obj .mgf .ply .gltf .glb), or a "
                    "solution's .vtp (its cells)")
        ->required();
    cmd->add_option("--scene", a->solution_scene,
                    "with a .vtp: the scene it solves (checked against the solution)");
    add_scene_flags(*cmd, a->scene_flags);
    cmd->add_option("--method", a->method,
                    "local (rays from each patch) or global (lines through the bounding sphere)")
        ->capture_default_str();
    cmd->add_option("--lines", a->lines, "local rays in all, or global lines")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_option("--seed", a->seed, "random seed")
        ->transform(count_notation())
        ->capture_default_str();
    cmd->add_flag("--bounds", a->bounds,
                  "print the scene's bounding box, up axis guess, patches, emitters and views "
                  "instead (what writing a view takes)");
    cmd->add_flag("--json", a->json, "machine-readable output");
    return {cmd, [a] { return run_info(*a); }};
}

}  // namespace hmcr
