// SPDX-License-Identifier: Apache-2.0
// References of both kinds, `hmcr error` and the studies' checks of their reference, as a user
// runs them: the files each writes, the kind's flags kept apart, a warning exactly where cells
// are finer than the reference, `hmcr error` giving a study cell's own numbers, and a study that
// resumes from a copy of its folder.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "image/image.h"
#include "studies/point_reference.h"
#include "tests/hostile/hostile.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

class ReferenceCli : public Hostile {
protected:
    nlohmann::json json_of(const fs::path& file) const {
        return nlohmann::json::parse(read_file(m_temp.path() / file));
    }
    // A small meshing study of the plates against `reference`, into `out`.
    CliRun study(const std::string& reference, const std::string& out,
                 const std::string& more = "") const {
        return run("study plates.json --reference " + reference +
                   " --budgets 20 --budget-tolerance 0.1 --oracles power --seeds 2 --rays 20000 "
                   "--mesh-rays 20000 -o " +
                   out + " " + more);
    }
    CliRun run(const std::string& args) const { return run_hmcr(args, m_temp.path(), 120); }
};

TEST_F(ReferenceCli, APointReferenceWritesItsPointsViewsAndReport) {
    plates();
    const CliRun r = run("reference plates.json --points 400 --paths 16 --spp 4 -o ref");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("point reference of 400 points"), std::string::npos) << r.out;
    for (const char* f : {"points.vtp", "reference.json", "views/side.pfm", "views/side.png"}) {
        EXPECT_TRUE(fs::exists(m_temp.path() / "ref" / f)) << f;
    }
    const nlohmann::json ref = json_of("ref/reference.json")["reference"];
    EXPECT_EQ(ref["kind"], "points");
    EXPECT_EQ(ref["points"], 400);
    EXPECT_EQ(ref["paths"], 16);
    EXPECT_GT(ref["report"]["noise"].get<double>(), 0);
    EXPECT_TRUE(fs::path(ref["scene_file"].get<std::string>()).is_absolute());
}

TEST_F(ReferenceCli, ANoisyPointReferenceWarnsWithThePathsThatQuietIt) {
    plates();
    const CliRun noisy = run("reference plates.json --points 400 --paths 2 --spp 1 -o noisy");
    ASSERT_EQ(noisy.exit_code, 0) << noisy.err;
    const double noise = json_of("noisy/reference.json")["reference"]["report"]["noise"];
    ASSERT_GT(noise, kNoiseWarning);
    EXPECT_NE(noisy.err.find(
                  fmt::format("--paths {} brings it to about", paths_for_target_noise(noise, 2))),
              std::string::npos)
        << noisy.err;
    const CliRun quiet = run("reference plates.json --points 400 --paths 4096 --spp 1 -o quiet");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    ASSERT_LT(json_of("quiet/reference.json")["reference"]["report"]["noise"].get<double>(),
              kNoiseWarning);
    EXPECT_EQ(quiet.err.find("noise"), std::string::npos) << quiet.err;
}

TEST_F(ReferenceCli, AMeshFlagMakesAMeshReferenceThatChecksItselfAgainstPoints) {
    plates();
    const CliRun r = run("reference plates.json --max-area 0.1 --rays 20000 -o ref");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The flag that made it one is named: a --sequence meant for the judged solves would do so.
    EXPECT_NE(r.out.find("plates: a mesh reference, since --rays is given (--kind points for a "
                         "point reference)"),
              std::string::npos)
        << r.out;
    const nlohmann::json summary = json_of("ref/reference.json");
    const nlohmann::json& ref = summary["reference"];
    const auto points = 4 * summary["counts"]["leaves"].get<std::uint64_t>();  // 4 an element
    // The counts the summary has, by its names.
    EXPECT_NE(r.out.find(fmt::format("reference of {} leaves ({} elements with their parents)",
                                     summary["counts"]["leaves"].get<std::uint64_t>(),
                                     summary["counts"]["elements"].get<std::uint64_t>())),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("against " + std::to_string(points) + " points the mesh is off by"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(ref.contains("kind"));
    EXPECT_EQ(ref["discretisation"]["check_points"], points);
    EXPECT_GT(ref["discretisation"]["relative_l2"].get<double>(), 0);
}

TEST_F(ReferenceCli, TheKindsFlagsAreKeptApart) {
    plates();
    const auto before = snapshot(m_temp.path());
    refused("reference plates.json --points 100 --max-area 0.1 -o ref",
            "--points is for a point reference; this one is a mesh reference (--max-area makes "
            "it one; --kind points asks for points)");
    refused("reference plates.json --kind points --max-area 0.1 -o ref",
            "--max-area is for a mesh reference; this one is a point reference");
    refused("reference plates.json --kind mesh --paths 8 -o ref",
            "--paths is for a point reference; this one is a mesh reference");
    refused("reference plates.json --kind points --sequence sobol -o ref",
            "--sequence is for a mesh reference; this one is a point reference");
    // Settings of a refining solve, which a uniform mesh and the points have no use for.
    refused("reference plates.json --importance views -o ref", "--importance");
    refused("reference plates.json --link-weight total -o ref", "--link-weight");
    refused("reference plates.json --kind cloud -o ref", "kind must be auto, points or mesh");
    refused("reference plates.json --paths 1 -o ref", "paths must be at least 2");
    refused("reference plates.json --for-budget 0 -o ref", "not a positive leaf count");
    EXPECT_EQ(snapshot(m_temp.path()), before);
}

// The help says what the study takes: spp values, not one spp; what the tolerance is relative to.
TEST_F(ReferenceCli, StudysHelpSaysWhatItTakes) {
    const CliRun top = run("--help"), study = run("study --help");
    EXPECT_NE(top.out.find("pixel samplers at spp values (--samplers)"), std::string::npos)
        << top.out;
    EXPECT_EQ(top.out.find("one spp"), std::string::npos) << top.out;
    EXPECT_NE(study.out.find("accepted relative distance of a cell's leaf count to its budget"),
              std::string::npos)
        << study.out;
    plates();
    refused("study plates.json --reference ref --budgets 20 --budget-tolerance 2 -o out",
            "study: budget-tolerance 2 is not in (0, 1)");
}

TEST_F(ReferenceCli, ForBudgetSizesTheReferenceAndSaysSo) {
    plates();
    const CliRun r = run("reference plates.json --for-budget 30000 --paths 2 --spp 1 -o ref");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("for studies up to 30000 leaves: --points 600000"), std::string::npos)
        << r.out;
    EXPECT_EQ(json_of("ref/reference.json")["reference"]["points_target"], 600000);
}

// A coarse mesh reference of 2 elements judges cells of 20 leaves: warned; --strict refuses;
// against 10^5 points the same cells are not finer, and nothing is said.
TEST_F(ReferenceCli, TheStudyWarnsExactlyWhereItsCellsAreFinerThanTheReference) {
    plates();
    ASSERT_EQ(run("reference plates.json --max-area 1 --rays 20000 --check-points 0 -q -o coarse")
                  .exit_code,
              0);
    const CliRun warned = study("coarse", "st");
    ASSERT_EQ(warned.exit_code, 0) << warned.err;
    EXPECT_NE(warned.err.find("warning: at 20 leaves, 2 of 2 cells have more than 10%"),
              std::string::npos)
        << warned.err;
    EXPECT_NE(read_file(m_temp.path() / "st" / "table.md").find("**Warning:**"), std::string::npos);
    const CliRun strict = study("coarse", "st-strict", "--strict");
    EXPECT_EQ(strict.exit_code, 2);
    EXPECT_NE(strict.err.find("finer than the reference resolves"), std::string::npos)
        << strict.err;

    ASSERT_EQ(run("reference plates.json --points 100000 --paths 2 --spp 1 -q -o fine").exit_code,
              0);
    const CliRun quiet = study("fine", "st-fine");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_EQ(quiet.err.find("warning"), std::string::npos) << quiet.err;
    EXPECT_EQ(read_file(m_temp.path() / "st-fine" / "table.md").find("Warning"), std::string::npos);
}

// Pure black pixels in a box of an image.
int black(const Image8& im, int x0, int y0, int x1, int y1) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) n += im.at(x, y) == Srgb8{0, 0, 0};
    return n;
}

// A meshing study's figures: the reference's image and each oracle's side by side, the same
// with the elements' edges drawn, each tile labelled under it; and a ParaView state of every
// cell's mesh, each source named by its file, the first alone shown.
TEST_F(ReferenceCli, AStudyShowsItsOraclesSideBySideAndInParaView) {
    plates();
    ASSERT_EQ(run("reference plates.json --points 2000 --paths 4 --spp 1 -q -o ref").exit_code, 0);
    const CliRun r = run(
        "study plates.json --reference ref --budgets 20 --budget-tolerance 0.1 --oracles power,kl "
        "--seeds 1 --rays 20000 --mesh-rays 0 -q -o st");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image8 ref = read_png(m_temp.path() / "ref/views/side.png");
    const Image8 images = read_png(m_temp.path() / "st/figures/side-B20-images.png");
    const Image8 meshes = read_png(m_temp.path() / "st/figures/side-B20-meshes.png");
    const Image8 power = read_png(m_temp.path() / "st/images/plates-power-B20-s1-side.png");
    // 32-pixel tiles in columns as wide as "reference" (9 glyphs of 6 pixels, less one, and a
    // pixel each side: 55), under each a strip of 7 + 4 pixels.
    ASSERT_EQ(ref.width, 32);
    EXPECT_EQ(images.width, 3 * 55 + 2 * 2);
    EXPECT_EQ(images.height, 32 + 11);
    EXPECT_EQ(meshes.width, 2 * 32 + 2);  // power and kl: labels narrower than the tiles
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            EXPECT_EQ(images.at(11 + x, y), ref.at(x, y)) << x << ", " << y;
            EXPECT_EQ(images.at(57 + 11 + x, y), power.at(x, y)) << x << ", " << y;
        }
    EXPECT_GT(black(images, 0, 32, 55, 43), 0);                          // "reference"
    EXPECT_GT(black(images, 57, 32, 112, 43), 0);                        // "power"
    EXPECT_GT(black(meshes, 0, 0, 32, 32), black(power, 0, 0, 32, 32));  // the edges
    const std::string pvsm = read_file(m_temp.path() / "st/meshes.pvsm");
    EXPECT_NE(pvsm.find(R"(name="plates-power-B20-s1.vtp")"), std::string::npos) << pvsm;
    EXPECT_NE(pvsm.find(R"(name="plates-kl-B20-s1.vtp")"), std::string::npos) << pvsm;
    EXPECT_NE(pvsm.find((m_temp.path() / "st/meshes/plates-kl-B20-s1.vtp").string()),
              std::string::npos);
    EXPECT_NE(
        pvsm.find(
            R"(name="PreviewMode" id="5.PreviewMode" number_of_elements="2"><Element index="0" value="32"/>)"),
        std::string::npos);
}

// `hmcr error` on a study's own cell gives the cell file's numbers, bit for bit; read as a
// foreign solution (its polygons, Radiosity and PatchId alone) it gives them too.
TEST_F(ReferenceCli, ErrorOnAStudysCellGivesTheTablesNumbers) {
    plates();
    ASSERT_EQ(run("reference plates.json --points 2000 --paths 16 --spp 4 -q -o ref").exit_code, 0);
    ASSERT_EQ(study("ref", "st").exit_code, 0);
    const std::string cell = "plates-power-B20-s1";
    const nlohmann::json c = json_of("st/cells/" + cell + ".json");
    for (const char* foreign : {"", " --foreign"}) {
        const CliRun e = run("error st/meshes/" + cell + ".vtp --reference ref -q -o e.json" +
                             std::string(foreign));
        ASSERT_EQ(e.exit_code, 0) << e.err;
        const nlohmann::json m = json_of("e.json");
        EXPECT_EQ(m["object_error"], c["object_error"]) << foreign;
        EXPECT_EQ(m["views"], c["views"]) << foreign;
        EXPECT_EQ(m["finer_share"], c["finer_share"]) << foreign;
        fs::remove(m_temp.path() / "e.json");
    }
    refused("error st/meshes/" + cell + ".vtp --reference ref -o e.txt",
            "output must be a .json file");
}

TEST_F(ReferenceCli, AStudyResumesFromACopyOfItsFolderAndAnAbsoluteScenePath) {
    plates();
    ASSERT_EQ(run("reference plates.json --points 400 --paths 4 --spp 2 -q -o ref").exit_code, 0);
    ASSERT_EQ(study("ref", "st").exit_code, 0);
    fs::create_directories(m_temp.path() / "elsewhere");
    fs::copy(m_temp.path() / "st", m_temp.path() / "elsewhere" / "st", fs::copy_options::recursive);
    fs::remove(m_temp.path() / "elsewhere" / "st" / "table.md");
    const std::string scene = (m_temp.path() / "plates.json").string();
    const CliRun again = run_hmcr("study " + scene +
                                      " --reference ../ref --budgets 20 --oracles "
                                      "power --seeds 2 --rays 20000 --mesh-rays 20000 "
                                      "--budget-tolerance 0.1 -o st",
                                  m_temp.path() / "elsewhere", 120);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.err.find("rendering"), std::string::npos) << again.err;  // nothing computed
    EXPECT_TRUE(fs::exists(m_temp.path() / "elsewhere" / "st" / "table.md"));
}

}  // namespace
}  // namespace hmcr::test
