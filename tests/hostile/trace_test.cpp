// SPDX-License-Identifier: Apache-2.0
// Hostile input to the path tracer's commands (`trace`, `trace-reference`, `study --samplers`):
// every bad option is refused before any tracing with one line and exit code 2, no output goes
// over an input, and a study of one kind refuses the other kind's flags.
#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

TEST_F(Hostile, TraceOptionsAreChecked) {
    plates();
    const std::pair<std::string, std::string> cases[] = {
        {"--spp 0", "spp must be a whole number in 1..1e6 for the uniform sampler, got 0"},
        {"--spp 1.5", "spp must be a whole number in 1..1e6"},
        {"--spp nan", "--spp: 'nan' is not a finite number"},
        {"--spp inf", "--spp: 'inf' is not a finite number"},
        {"--spp 1e7", "spp must be a whole number in 1..1e6"},
        {"--spp many", "--spp"},
        {"--sampler kl --spp 4", "spp must be in 8..32 for sampler kl"},
        {"--sampler kl --spp 20 --max-spp 16", "spp must be in 8..16 for sampler kl"},
        {"--sampler kl --max-spp 3", "max-spp must be in 8..1000000, got 3"},
        {"--sampler entropy --spp 2000", "spp must be in 4..1024 for sampler entropy"},
        {"--sampler nope", "unknown sampler 'nope' (valid: uniform, cc, var"},
        {"--sampler kl --threshold -1", "threshold must be positive"},
        {"--sampler kl --allocation map --threshold 0.01",
         "threshold is for --allocation refine: map spends --spp by the criterion's map"},
        {"--sampler kl --spp-tolerance 0", "spp-tolerance must be in (0, 1)"},
        {"--sampler entropy --tree-depth 13", "tree-depth must be in 1..12"},
        {"--estimator fast", "estimator must be mis, nee or bsdf"},
        {"--bounces -1", "bounces must be in 0..100000"},
        {"--threads -1", "threads must be in 0..4096"},
        {"--width -4", "width must be in 1..16384"},
        {"--view top", "no view 'top' (views: side)"},
        {"--progress loud", "progress must be auto, bar, lines or none"},
    };
    for (const auto& [option, needle] : cases)
        refused("trace plates.json -o x.png " + option, needle);
    for (const char* e : {"-1", "0"}) {
        refused("trace plates.json -o x.png --exposure " + std::string(e),
                "exposure must be a positive number, got " + std::string(e));
    }
    refused("trace plates.json -o x.png --reference nowhere", "nowhere/reference.json");
    refused("trace plates.json -o x.png --exposure 1 --reference nowhere", "excludes");
}

TEST_F(Hostile, TraceWritesOverNoInput) {
    plates();
    refused("trace plates.json -o x.jpg", "output must be a .png file");
    refused("trace plates.json -o x.png --pfm x.png", "pfm must be a .pfm file");
    // The summary goes beside the image: plates.png would put it over plates.json.
    refused("trace plates.json -o plates.png", "is an input of this command");
    std::filesystem::create_symlink(dir() / "plates.obj", dir() / "link.pfm");
    refused("trace plates.json -o x.png --pfm link.pfm", "is an input of this command");
    std::filesystem::create_directory(dir() / "x-density.png");
    refused("trace plates.json -o x.png", "cannot write x-density.png: it is a folder");
}

TEST_F(Hostile, TraceReferenceChecksItsFolder) {
    plates();
    m_temp.write("file", "x");
    refused("trace-reference plates.json --spp 4 -o file", "cannot write file: it is not a folder");
    refused("trace-reference plates.json --spp 0 -o ref", "spp must be a whole number");
    refused("trace-reference plates.json --sampler kl -o ref", "--sampler");
    // A reference.json that is a link to the scene file.
    std::filesystem::create_symlink(dir() / "plates.json", dir() / "reference.json");
    refused("trace-reference plates.json --spp 4 -o .", "is an input of this command");
}

TEST_F(Hostile, SamplingStudyOptionsAreChecked) {
    plates();
    accepted("trace-reference plates.json --spp 8 --width 8 -q -o ref");
    const auto before = snapshot(dir());
    const std::string study = "study plates.json --reference ref -o s ";
    const std::pair<std::string, std::string> cases[] = {
        {"", "give --budgets (a meshing study) or --samplers (a sampling study)"},
        {"--samplers uniform --budgets 5", "not both"},
        {"--samplers uniform --rays 1000", "--rays is for a meshing study"},
        {"--samplers uniform --oracles kl", "--oracles is for a meshing study"},
        {"--budgets 5 --spp 8", "--spp is for a sampling study"},
        {"--budgets 5 --estimator nee", "--estimator is for a sampling study"},
        {"--samplers nope", "unknown sampler 'nope'"},
        {"--samplers uniform,kl,uniform", "sampler uniform is given twice"},
        {"--samplers uniform,,kl", "empty item in the list"},
        {"--samplers kl --spp 4", "spp must be in 8..32 for sampler kl"},
        {"--samplers uniform --spp 7.5", "spp must be a whole number"},
        {"--samplers all --seeds 0", "seeds must be at least 1"},
        {"--samplers uniform --bounces -2", "bounces must be in 0..100000"},
    };
    for (const auto& [option, needle] : cases) refused(study + option, needle);
    // More spp values than a plot shows: refused before the first cell, not after the last.
    std::string spps = "1";
    for (int spp = 2; spp <= 1001; ++spp) {
        spps += ',';
        spps += std::to_string(spp);
    }
    refused(study + "--samplers uniform --spp " + spps,
            "study: 1001 spp values; at most 1000, the points a plot shows");
    refused("study plates.json --samplers uniform --reference ref -o ref/s", "lies in the input");
    refused("study plates.json --samplers uniform --reference nowhere -o s",
            "nowhere/reference.json");
    EXPECT_TRUE(snapshot(dir()) == before);
}

}  // namespace
}  // namespace hmcr::test
