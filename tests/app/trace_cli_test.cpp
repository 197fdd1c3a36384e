// SPDX-License-Identifier: Apache-2.0
// `hmcr trace` and `hmcr samplers` as a user meets them: the image, its density map and its
// summary; bad input gets one line, exit code 2 and no file, before any tracing.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

namespace fs = std::filesystem;

class TraceCli : public testing::Test {
protected:
    CliRun hmcr(const std::string& args) const { return run_hmcr(args, m_dir); }
    std::string out() const { return " -o " + (m_dir / "im.png").string(); }
    void expect_clean_failure(const std::string& args, const std::string& needle) const {
        const CliRun r = hmcr(args + out());
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(m_dir / "im.png"));
        EXPECT_FALSE(fs::exists(m_dir / "im.json"));
    }
    TempDir m_temp;
    const fs::path& m_dir = m_temp.path();
};

TEST_F(TraceCli, WritesTheImageItsDensityMapAndASummary) {
    const CliRun r = hmcr(
        "trace cornell --view corner --width 24 --sampler srhe --spp 12 "
        "--seed 4 --pfm " +
        (m_dir / "im.pfm").string() + out());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_png(m_dir / "im.png").width, 24);
    EXPECT_EQ(read_png(m_dir / "im-density.png").height, 24);
    EXPECT_EQ(read_pfm(m_dir / "im.pfm").width, 24);
    const auto j = nlohmann::json::parse(read_file(m_dir / "im.json"));
    EXPECT_EQ(j["scene"], "cornell");
    EXPECT_EQ(j["view"], "corner");
    EXPECT_EQ(j["sampler"], "srhe");
    EXPECT_EQ(j["spp"]["target"], 12.0);
    EXPECT_NEAR(j["spp"]["achieved"].get<double>(), 12, 0.24);
    EXPECT_LE(j["spp"]["min"].get<double>(), j["spp"]["achieved"].get<double>());
    EXPECT_GE(j["spp"]["max"].get<double>(), j["spp"]["achieved"].get<double>());
    EXPECT_GT(j["threshold"].get<double>(), 0);
    EXPECT_FALSE(j["threshold_probes"].empty());
    EXPECT_GE(j["rays"]["traced"].get<double>(), j["rays"]["image"].get<double>());
    EXPECT_GT(j["seconds"].get<double>(), 0);
    EXPECT_EQ(j["seed"], 4);
}

TEST_F(TraceCli, UniformHasNoThreshold) {
    ASSERT_EQ(hmcr("trace plates --width 16 --spp 3 --exposure 2" + out()).exit_code, 0);
    const auto j = nlohmann::json::parse(read_file(m_dir / "im.json"));
    EXPECT_TRUE(j["threshold"].is_null());
    EXPECT_EQ(j["spp"]["min"], 3);
    EXPECT_EQ(j["spp"]["max"], 3);
    EXPECT_EQ(j["exposure"], 2.0);
}

// A traced reference folder serves `trace --reference` (its exposure) and `study --samplers`.
TEST_F(TraceCli, TraceReferenceAndSamplingStudyWriteTheirFiles) {
    const std::string ref = (m_dir / "ref").string(), study = (m_dir / "study").string();
    ASSERT_EQ(hmcr("trace-reference plates --width 10 --spp 16 -o " + ref).exit_code, 0);
    const auto j = nlohmann::json::parse(read_file(m_dir / "ref" / "reference.json"));
    EXPECT_EQ(j["reference"]["kind"], "traced");
    EXPECT_EQ(j["reference"]["spp"], 16.0);
    const double exposure = j["reference"]["views"]["oblique"]["exposure"].get<double>();
    EXPECT_EQ(read_pfm(m_dir / "ref" / "views" / "side.pfm").width, 10);
    ASSERT_EQ(hmcr("trace plates --view oblique --width 10 --reference " + ref + out()).exit_code,
              0);
    EXPECT_EQ(nlohmann::json::parse(read_file(m_dir / "im.json"))["exposure"], exposure);
    const CliRun r = hmcr("study plates --reference " + ref +
                          " --samplers uniform,srhe --spp 8 --seeds 1 -q -o " + study);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(m_dir / "study" / "cells" / "plates-srhe-spp8-s1.json"));
    EXPECT_NE(read_file(m_dir / "study" / "table.md").find("| srhe | 1/1 |"), std::string::npos);
    EXPECT_NE(read_file(m_dir / "study" / "table.tex").find("\\label{tab:plates-sampling}"),
              std::string::npos);
    // Its plots, drawn again from its table.json: the same numbers.
    const fs::path data = m_dir / "study" / "plots" / "plot_data.json";
    const std::string drawn = read_file(data);
    EXPECT_NE(drawn.find("\"error_by_sampler\""), std::string::npos) << drawn;
    EXPECT_TRUE(fs::exists(m_dir / "study" / "plots" / "error_by_sampler.pdf"))
        << "no matplotlib? make deps installs python3-matplotlib";
    EXPECT_TRUE(fs::exists(m_dir / "study" / "plots" / "error_by_sampler.png"));
    fs::remove(data);
    EXPECT_EQ(hmcr("plot -q " + study).exit_code, 0);
    EXPECT_EQ(read_file(data), drawn);
}

// `hmcr study --budgets` against a traced reference: radiosity solutions measured against an
// independent solution of the same light transport. There is no reference mesh, so no
// object-space error ("–" in the table, null in the cells), and the plot shows RMSEp. The plots,
// drawn at the end (PDF and PNG), are drawn again by `hmcr plot`.
TEST_F(TraceCli, AMeshingStudyTakesATracedReference) {
    const std::string ref = (m_dir / "ref").string(), study = (m_dir / "study").string();
    ASSERT_EQ(hmcr("trace-reference plates --width 12 --spp 64 -q -o " + ref).exit_code, 0);
    const CliRun r = hmcr("study plates --reference " + ref +
                          " --budgets 20 --oracles power,kl --seeds 1 --rays 20000 -q -o " + study);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string md = read_file(m_dir / "study" / "table.md");
    EXPECT_NE(md.find("| power | 1/1 |"), std::string::npos) << md;
    const auto cell =
        nlohmann::json::parse(read_file(m_dir / "study" / "cells" / "plates-kl-B20-s1.json"));
    EXPECT_EQ(cell["status"], "ok");
    EXPECT_TRUE(cell["object_error"]["relative_l2"].is_null());
    for (const auto& [view, e] : cell["views"].items()) {
        EXPECT_GT(e["psnr_p"].get<double>(), 15) << view;  // the same scene, solved both ways
    }
    EXPECT_EQ(read_png(m_dir / "study" / "images" / "plates-kl-B20-s1-side.png").width, 12);
    const fs::path plots = m_dir / "study" / "plots";
    const auto data = nlohmann::json::parse(read_file(plots / "plot_data.json"));
    EXPECT_EQ(data["figures"][0]["panels"][0]["y_label"], "RMSEp (0–255)");
    const auto drawn = [&] {
        return read_file(plots / "error_vs_elements.pdf").rfind("%PDF-", 0) == 0 &&
               read_file(plots / "error_vs_elements.png").rfind("\x89PNG\r\n\x1a\n", 0) == 0;
    };
    EXPECT_TRUE(drawn()) << "no matplotlib? make deps installs python3-matplotlib";
    fs::remove(plots / "error_vs_elements.pdf");
    fs::remove(plots / "error_vs_elements.png");
    const CliRun again = hmcr("plot " + study);
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.out, "plots written to " + (m_dir / "study" / "plots").string() + "\n");
    EXPECT_TRUE(drawn());
}

// --columns chooses the tables' columns and is no cell setting: a rerun with other columns
// resumes (no cell computed again, none refused) and writes the tables with its own columns.
TEST_F(TraceCli, OtherColumnsResumeAStudyAndRewriteOnlyItsTables) {
    const std::string ref = (m_dir / "ref").string(), study = (m_dir / "study").string();
    ASSERT_EQ(hmcr("trace-reference plates --width 8 --spp 16 -q -o " + ref).exit_code, 0);
    const std::string run =
        "study plates --reference " + ref + " --samplers uniform --spp 12 --seeds 2 -q -o " + study;
    ASSERT_EQ(hmcr(run + " --columns seeds,rmse_p").exit_code, 0);
    const fs::path cell = m_dir / "study" / "cells" / "plates-uniform-spp12-s2.json";
    const std::string cell_before = read_file(cell);
    const std::string md = read_file(m_dir / "study" / "table.md");
    EXPECT_NE(md.find("| sampler | seeds | RMSEp |\n"), std::string::npos) << md;

    const CliRun again = hmcr(run + " --columns psnr_p,spp");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(read_file(cell), cell_before);
    const std::string md_again = read_file(m_dir / "study" / "table.md");
    EXPECT_EQ(md_again.find("| RMSEp |"), std::string::npos) << md_again;
    EXPECT_NE(md_again.find("| sampler | PSNRp (dB) | spp |\n"), std::string::npos) << md_again;
    EXPECT_NE(read_file(m_dir / "study" / "table.tex").find("sampler & PSNRp (dB) & spp \\\\\n"),
              std::string::npos);
}

TEST_F(TraceCli, SamplersAreListed) {
    const CliRun r = hmcr("samplers");
    ASSERT_EQ(r.exit_code, 0);
    for (const char* name : {"uniform", "cc", "var", "entropy", "binary-entropy", "kl", "cs", "he",
                             "srkl", "srcs", "srhe"}) {
        EXPECT_NE(r.out.find(std::string(name) + " "), std::string::npos) << name;
    }
}

}  // namespace
}  // namespace hmcr::test
