// SPDX-License-Identifier: Apache-2.0
// A tiny sampling study (studies/sampling_study.h) against a tiny traced reference
// (studies/traced_reference.h): every documented file, resuming after a deleted cell, and a
// search that cannot succeed recorded as a failed cell.
#include "studies/sampling_study.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "studies/reference.h"
#include "studies/traced_reference.h"
#include "tests/support/plugins.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

// Counts the study's notes "[i/n] CELL: done before, skipped" and "[i/n] CELL: ok (...)".
class Counting final : public Progress {
public:
    void stage(std::string_view) override {}
    void advance(double) override {}
    void note(std::string_view line) override {
        const std::string s(line);
        if (s.find(": done before, skipped") != std::string::npos) ++skipped;
        if (s.find(": ok (") != std::string::npos || s.find(": failed (") != std::string::npos) {
            ++computed;
        }
    }
    int computed = 0, skipped = 0;
};

// The scene's views at size x size pixels, traced into dir with 64 uniform samples.
void write_small_reference(const Scene& scene, int size, const fs::path& dir) {
    std::vector<View> views = scene.views;
    for (View& v : views) v.width = v.height = size;
    TraceOptions o;
    o.spp = 64;
    OutputSet out(traced_reference_files(dir, scene), dir);
    write_traced_reference(out, dir, scene, compute_traced_reference(scene, views, o), o, "test");
    out.commit();
}

SamplingStudyOptions study(const fs::path& dir, std::vector<std::string> samplers, int seeds) {
    SamplingStudyOptions o;
    o.reference = dir / "ref";
    o.samplers.clear();
    for (const std::string& name : samplers) o.samplers.push_back(test::criterion(name));
    o.seeds = seeds;
    o.spps = {12};
    o.output = dir / "study";
    return o;
}

nlohmann::json without_seconds(nlohmann::json cell) {
    cell.erase("seconds");
    for (auto& [name, v] : cell["views"].items()) v.erase("seconds");
    return cell;
}

TEST(SamplingStudy, WritesEveryFileAndResumes) {
    const TempDir temp;
    const Scene scene = load_scene("cornell");
    write_small_reference(scene, 12, temp.path() / "ref");
    EXPECT_EQ(read_reference_exposures(temp.path() / "ref").size(), 2u);
    const SamplingStudyOptions o = study(temp.path(), {"uniform", "kl", "entropy"}, 2);
    run_sampling_study(scene, o);
    const std::string cell = "cornell-kl-spp12-s2";
    for (const char* f :
         {"table.md", "table.csv", "table.json", "figures/camera-images.png",
          "figures/corner-density.png", "images/cornell-kl-spp12-s2-corner.png",
          "density/cornell-entropy-spp12-s1-camera.png", "cells/cornell-kl-spp12-s2.json"}) {
        EXPECT_TRUE(fs::exists(o.output / f)) << f;
    }
    const std::string md = read_file(o.output / "table.md");
    for (const char* row : {"| uniform | 2/2 |", "| kl | 2/2 |", "| entropy | 2/2 |"}) {
        EXPECT_NE(md.find(row), std::string::npos) << row << "\n" << md;
    }
    const std::string csv = read_file(o.output / "table.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 6 * 2);  // header, cells x views
    const auto table = nlohmann::json::parse(read_file(o.output / "table.json"));
    EXPECT_EQ(table["cells"].size(), 6u);
    const auto before = nlohmann::json::parse(read_file(o.output / "cells" / (cell + ".json")));
    EXPECT_NEAR(before["views"]["camera"]["spp"].get<double>(), 12, 0.24);
    EXPECT_GT(before["views"]["camera"]["errors"]["rmse_a"].get<double>(), 0);
    // Figures: reference + 3 samplers, 4 to a row at full size (tiles under 128 pixels), each
    // column as wide as the widest label, "reference": 9 glyphs of 6 pixels less one, and one
    // pixel each side.
    EXPECT_EQ(read_png(o.output / "figures" / "camera-images.png").width, 4 * 55 + 3 * 2);

    fs::remove(o.output / "cells" / (cell + ".json"));
    Counting counting;
    run_sampling_study(scene, o, counting);
    EXPECT_EQ(counting.computed, 1);
    EXPECT_EQ(counting.skipped, 5);
    const auto after = nlohmann::json::parse(read_file(o.output / "cells" / (cell + ".json")));
    EXPECT_EQ(without_seconds(after), without_seconds(before));
}

// Several spp values: a cell per spp, sampler and seed; table.md once per spp; figures per spp;
// the allocation recorded in the cells' settings.
TEST(SamplingStudy, ASppListGivesCellsAndTablesPerSpp) {
    const TempDir temp;
    const Scene scene = load_scene("cornell");
    write_small_reference(scene, 8, temp.path() / "ref");
    SamplingStudyOptions o = study(temp.path(), {"uniform", "srhe"}, 2);
    o.spps = {12, 24};
    o.trace.allocation = Allocation::map;
    run_sampling_study(scene, o);
    for (const char* f : {"cells/cornell-srhe-spp12-s1.json", "cells/cornell-srhe-spp24-s2.json",
                          "cells/cornell-uniform-spp24-s1.json", "figures/camera-spp12-images.png",
                          "figures/corner-spp24-density.png"}) {
        EXPECT_TRUE(fs::exists(o.output / f)) << f;
    }
    const auto cell =
        nlohmann::json::parse(read_file(o.output / "cells" / "cornell-srhe-spp24-s1.json"));
    EXPECT_EQ(cell["spp"], 24);
    EXPECT_EQ(cell["settings"]["allocation"], "map");
    EXPECT_NEAR(cell["views"]["camera"]["spp"].get<double>(), 24, 1.0 / 64);
    const std::string md = read_file(o.output / "table.md");
    for (const char* line : {"12 samples per pixel", "24 samples per pixel",
                             "allocated from a map of 8 uniform samples per pixel"}) {
        EXPECT_NE(md.find(line), std::string::npos) << line << "\n" << md;
    }
    const auto table = nlohmann::json::parse(read_file(o.output / "table.json"));
    EXPECT_EQ(table["options"]["spp"], nlohmann::json({12, 24}));
    EXPECT_EQ(table["cells"].size(), 8u);
    EXPECT_TRUE(table["error_split"].contains("24"));
}

// Every face of a closed cube emits and reflects nothing: every sample sees the same radiance,
// so no divergence criterion can refine and no threshold reaches 12 samples per pixel.
TEST(SamplingStudy, UnreachableTargetIsAFailedCell) {
    const TempDir temp;
    std::string obj = read_file(scene_directory() / "furnace" / "furnace.obj");
    temp.write("glow/furnace.obj", obj);
    temp.write("glow/furnace.mtl", "newmtl furnace\nKd 0 0 0\nKe 0.5 0.5 0.5\n");
    temp.write("glow/glow.json",
               R"({"mesh": "furnace.obj", "views": [{"name": "inside", "position": [0.5, 0.5,)"
               R"( 0.05], "look_at": [0.5, 0.5, 1], "fov": 90, "width": 8, "height": 8}]})");
    const Scene scene = load_scene((temp.path() / "glow" / "glow.json").string());
    write_small_reference(scene, 8, temp.path() / "ref");
    const SamplingStudyOptions o = study(temp.path(), {"uniform", "kl"}, 1);
    run_sampling_study(scene, o);
    const auto kl = nlohmann::json::parse(read_file(o.output / "cells" / "glow-kl-spp12-s1.json"));
    EXPECT_EQ(kl["status"], "failed");
    EXPECT_NE(kl["message"].get<std::string>().find("nothing refines"), std::string::npos);
    const std::string md = read_file(o.output / "table.md");
    EXPECT_NE(md.find("| kl | 0/1 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| uniform | 1/1 |"), std::string::npos) << md;
}

TEST(SamplingStudy, BadOptionsAreInputErrors) {
    const TempDir temp;
    const Scene scene = load_scene("plates");
    EXPECT_THROW(run_sampling_study(scene, study(temp.path(), {"kl", "kl"}, 1)), InputError);
    EXPECT_THROW(run_sampling_study(scene, study(temp.path(), {"kl"}, 0)), InputError);
    EXPECT_THROW(run_sampling_study(scene, study(temp.path(), {"kl"}, 1)), InputError);  // no ref
    SamplingStudyOptions twice = study(temp.path(), {"kl"}, 1);
    twice.spps = {12, 12};
    EXPECT_THROW(run_sampling_study(scene, twice), InputError);
    twice.spps = {};
    EXPECT_THROW(run_sampling_study(scene, twice), InputError);
}

}  // namespace
}  // namespace hmcr::test
