// SPDX-License-Identifier: Apache-2.0
// A tiny meshing study on the Cornell box (studies/study.h): every documented file with its
// schema, and resuming: a rerun after one cell's file is deleted recomputes exactly that cell
// and reproduces the tables, the recomputed cell's timing aside.
#include <gtest/gtest.h>

#include <sstream>

#include "image/image.h"
#include "studies/reference.h"
#include "studies/study.h"
#include "tests/support/plugins.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream s(text);
    for (std::string line; std::getline(s, line);) out.push_back(line);
    return out;
}

// Counts the cells a run computed and skipped.
struct Counts {
    int computed = 0, skipped = 0;
    std::vector<std::string> computed_cells;
};

// Reads the study's notes: "[i/n] CELL: done before, skipped", "[i/n] CELL: done (...)",
// "[i/n] CELL: budget not reached, ...".
class Counting final : public Progress {
public:
    explicit Counting(Counts& counts) : m_counts(counts) {}
    void stage(std::string_view) override {}
    void advance(double) override {}
    void note(std::string_view line) override {
        const std::string s(line);
        const auto close = s.find("] "), colon = s.find(": ");
        ASSERT_EQ(s.front(), '[') << s;
        ASSERT_NE(colon, std::string::npos) << s;
        const std::string cell = s.substr(close + 2, colon - close - 2), what = s.substr(colon + 2);
        if (what == "done before, skipped") ++m_counts.skipped;
        if (what.rfind("done (", 0) == 0 || what.rfind("budget not reached", 0) == 0) {
            ++m_counts.computed;
            m_counts.computed_cells.push_back(cell);
        }
    }

private:
    Counts& m_counts;
};

// table.json without the timings of one cell (every "seconds", the probes' included).
nlohmann::json without_timing(nlohmann::json table, const std::string& cell) {
    for (auto& c : table["cells"]) {
        if (cell_name(c["scene"], c["oracle"], c["budget"], c["seed"]) != cell) continue;
        c.erase("seconds");
        for (auto& p : c["probe_history"]) p.erase("seconds");
    }
    return table;
}

// Markdown table rows without their last column (seconds).
std::string without_last_column(const std::string& md) {
    std::string out;
    for (const std::string& line : lines_of(md)) {
        const auto cut = line.rfind(" | ", line.size() - 2);
        out += (line.rfind("| ", 0) == 0 && cut != std::string::npos ? line.substr(0, cut) : line) +
               "\n";
    }
    return out;
}

class TinyStudy : public testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = new TempDir;
        s_cornell = new Scene(load_scene("cornell"));
        const Scene& scene = *s_cornell;
        ReferenceOptions ro;
        ro.max_area = 4e-3;
        ro.solver.rays = 2'000'000;
        const std::filesystem::path ref = s_dir->path() / "ref";
        OutputSet out(reference_files(ref, scene), ref);
        write_reference(out, ref, scene, compute_reference(scene, ro), ro, {});
        out.commit();
    }
    static void TearDownTestSuite() {
        delete s_dir;
        delete s_cornell;
    }
    static const Scene& s_scene() { return *s_cornell; }

    StudyOptions options() const {
        StudyOptions o;
        o.reference = s_dir->path() / "ref";
        o.budgets = {200};
        o.oracles = {test::oracle("power"), test::oracle("kl")};
        o.seeds = 2;
        o.solver.rays = 200'000;
        // Refined cells: their links' error makes the frozen re-solve's error clearly lower
        // (a frozen cell of 200 leaves is already within its noise of the mesh's own error).
        o.solver.refine_share = 1;
        o.mesh_rays = 2'000'000;
        o.output = m_out.path();
        return o;
    }

    static TempDir* s_dir;
    static Scene* s_cornell;
    TempDir m_out;
};

TempDir* TinyStudy::s_dir = nullptr;
Scene* TinyStudy::s_cornell = nullptr;

TEST_F(TinyStudy, WritesEveryFileWithTheDocumentedSchemaAndResumes) {
    const StudyOptions o = options();
    Counts first;
    Counting first_notes(first);
    run_study(s_scene(), o, first_notes);
    EXPECT_EQ(first.computed, 4);
    EXPECT_EQ(first.skipped, 0);
    const std::filesystem::path out = o.output;

    const nlohmann::json table = nlohmann::json::parse(read_file(out / "table.json"));
    ASSERT_EQ(table.at("cells").size(), 4u);
    EXPECT_EQ(table.at("views"), nlohmann::json({"camera", "corner"}));
    for (const auto& c : table["cells"]) {
        for (const char* key : {"scene", "oracle", "budget", "seed", "status", "epsilon", "leaves",
                                "probes", "seconds", "views", "object_error", "rays", "mesh_rays",
                                "mesh_views", "mesh_object_error"})
            EXPECT_TRUE(c.contains(key)) << key;
        ASSERT_EQ(c["status"], "ok") << c["message"];
        EXPECT_NEAR(double(c["leaves"]), 200, 2.0);
        // Computed: an all-black solution would score exactly 1, a missing one NaN.
        EXPECT_GT(double(c["object_error"]["relative_l2"]), 0.0);
        EXPECT_LT(double(c["object_error"]["relative_l2"]), 1.0);
        // The same mesh with ten times the rays: error^2 = mesh^2 + noise^2 with less noise.
        EXPECT_EQ(c["rays"], 200'000);
        EXPECT_EQ(c["mesh_rays"], 2'000'000);
        EXPECT_GT(double(c["mesh_object_error"]["relative_l2"]), 0.0);
        EXPECT_LT(double(c["mesh_object_error"]["relative_l2"]),
                  double(c["object_error"]["relative_l2"]));
        for (const char* view : {"camera", "corner"}) {
            for (const char* key : {"rmse_a", "rmse_p", "psnr_a", "psnr_p"})
                EXPECT_TRUE(c["views"][view].contains(key)) << view << " " << key;
        }
        const std::string name = cell_name(c["scene"], c["oracle"], c["budget"], c["seed"]);
        EXPECT_TRUE(std::filesystem::exists(out / "cells" / (name + ".json"))) << name;
        EXPECT_TRUE(std::filesystem::exists(out / "meshes" / (name + ".vtp"))) << name;
        EXPECT_TRUE(std::filesystem::exists(out / "meshes" / (name + "-mesh.vtp"))) << name;
        for (const char* view : {"camera", "corner"}) {
            EXPECT_EQ(read_png(out / "images" / (name + "-" + view + ".png")).width, 512);
            EXPECT_EQ(read_png(out / "images" / (name + "-mesh-" + view + ".png")).width, 512);
        }
    }

    const std::vector<std::string> csv = lines_of(read_file(out / "table.csv"));
    ASSERT_EQ(csv.size(), 1u + 4 * 2);  // header, one row per cell and view
    EXPECT_EQ(csv[0].rfind("scene,oracle,budget,seed,status,epsilon,leaves,probes,seconds,view,"
                           "rmse_a,rmse_p,psnr_a,psnr_p,object_error",
                           0),
              0u);
    EXPECT_NE(csv[0].find(",mesh_rmse_a,mesh_rmse_p,mesh_psnr_a,mesh_psnr_p,mesh_object_error,"),
              std::string::npos);

    const std::string md = read_file(out / "table.md");
    int rows = 0;
    for (const std::string& line : lines_of(md))
        rows += line.rfind("| power | 2/2 |", 0) == 0 || line.rfind("| kl | 2/2 |", 0) == 0;
    EXPECT_EQ(rows, 2) << md;
    EXPECT_NE(md.find("**"), std::string::npos) << md;  // the best values are bold
    EXPECT_NE(md.find("| mesh PSNRp (dB) | mesh object error |"), std::string::npos) << md;

    // meshes.pvd: every cell's mesh, one ParaView time step each, named relative to the study.
    const std::string pvd = read_file(out / "meshes.pvd");
    for (const auto& c : table["cells"]) {
        const std::string name = cell_name(c["scene"], c["oracle"], c["budget"], c["seed"]);
        EXPECT_NE(pvd.find("file=\"meshes/" + name + ".vtp\""), std::string::npos) << pvd;
    }
    EXPECT_NE(pvd.find("timestep=\"3\""), std::string::npos) << pvd;

    // The plots' numbers: the solution's and the mesh's panels; the LaTeX table beside table.md.
    const nlohmann::json plots = nlohmann::json::parse(read_file(out / "plots" / "plot_data.json"));
    EXPECT_EQ(plots["figures"][0]["panels"].size(), 2u);
    EXPECT_NE(read_file(out / "table.tex").find("\\label{tab:cornell-200}"), std::string::npos);

    // Resume: only the deleted cell is computed again.
    const std::string deleted = cell_name("cornell", "kl", 200, 2);
    std::filesystem::remove(out / "cells" / (deleted + ".json"));
    Counts second;
    Counting second_notes(second);
    run_study(s_scene(), o, second_notes);
    EXPECT_EQ(second.computed, 1);
    EXPECT_EQ(second.skipped, 3);
    EXPECT_EQ(second.computed_cells, std::vector<std::string>{deleted});
    const nlohmann::json again = nlohmann::json::parse(read_file(out / "table.json"));
    EXPECT_EQ(without_timing(again, deleted), without_timing(table, deleted));
    EXPECT_EQ(without_last_column(read_file(out / "table.md")), without_last_column(md));
}

TEST_F(TinyStudy, RecordsAnUnreachableBudgetAsAFailedCell) {
    StudyOptions o = options();
    o.budgets = {5};  // fewer leaves than the Cornell box has patches
    o.oracles = {test::oracle("power")};
    o.seeds = 1;
    Counts counts;
    Counting counts_notes(counts);
    run_study(s_scene(), o, counts_notes);
    EXPECT_EQ(counts.computed, 1);
    const nlohmann::json table = nlohmann::json::parse(read_file(o.output / "table.json"));
    ASSERT_EQ(table.at("cells").size(), 1u);
    EXPECT_EQ(table["cells"][0]["status"], "failed");
    EXPECT_FALSE(std::string(table["cells"][0]["message"]).empty());
    EXPECT_NE(read_file(o.output / "table.md").find("| power | 0/1 |"), std::string::npos);
}

// --rays-per-leaf: each budget's cells shoot that many rays per leaf of the budget; --mesh-rays
// 0 measures no mesh error, and the tables say so.
TEST_F(TinyStudy, RaysPerLeafScaleWithTheBudget) {
    StudyOptions o = options();
    o.budgets = {100, 200};
    o.oracles = {test::oracle("power")};
    o.seeds = 1;
    o.rays_per_leaf = 500;
    o.mesh_rays = 0;
    run_study(s_scene(), o);
    const nlohmann::json table = nlohmann::json::parse(read_file(o.output / "table.json"));
    ASSERT_EQ(table.at("cells").size(), 2u);
    EXPECT_EQ(table["cells"][0]["rays"], 50'000);
    EXPECT_EQ(table["cells"][1]["rays"], 100'000);
    for (const auto& c : table["cells"]) {
        EXPECT_EQ(c["mesh_rays"], 0);
        EXPECT_TRUE(c["mesh_object_error"].is_null()) << c;  // not measured, not a perfect 0
        EXPECT_TRUE(c["mesh_views"].is_null()) << c;
    }
    const std::string md = read_file(o.output / "table.md");
    EXPECT_NE(md.find("500 rays per leaf of the budget"), std::string::npos) << md;
    EXPECT_NE(md.find("mesh: not measured (--mesh-rays 0)"), std::string::npos) << md;
}

}  // namespace
}  // namespace hmcr::test
