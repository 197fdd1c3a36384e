// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a study's cell files (cells/CELL.json) of either kind, as a resumed study
// reads them: each reader refuses what it cannot take, and what it takes checks out (no count
// wrapped from a negative number, no error or time below zero, a known status).
#include <cmath>
#include <cstdint>

#include "common/text_file.h"
#include "studies/sampling_study.h"
#include "studies/study.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using hmcr::fuzz::crash;

void check(double value, const char* what) {
    if (value < 0) crash(std::string("a negative ") + what);  // NaN: not measured
}

void check(const hmcr::ImageErrors& e) {
    check(e.rmse_a, "RMSE");
    check(e.rmse_p, "RMSE");
    check(e.psnr_a, "PSNR");
    check(e.psnr_p, "PSNR");
}

void check(const hmcr::CellResult& c) {
    if (!c.ok() && c.status != "failed") crash("an unknown status");
    check(c.object_error.relative_l2, "object error");
    check(c.mesh_object_error.relative_l2, "mesh object error");
    check(c.epsilon, "epsilon");
    check(c.seconds, "time");
    for (const auto& [view, e] : c.views) check(e);
    for (const auto& [view, e] : c.mesh_views) check(e);
    (void)hmcr::cell_to_json(c).dump();  // what the tables then do with it
}

void check(const hmcr::SamplingCell& c) {
    if (!c.ok() && c.status != "failed") crash("an unknown status");
    if (!(c.spp > 0)) crash("a target spp that is not positive");
    check(c.seconds, "time");
    for (const auto& [view, v] : c.views) {
        check(v.errors);
        check(v.spp, "spp");
        check(v.threshold, "threshold");
    }
    (void)hmcr::sampling_cell_to_json(c).dump();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const auto cell = write("cell.json", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        check(hmcr::read_json_file(
            cell, [](const nlohmann::json& j) { return hmcr::cell_from_json(j); }));
    });
    expect_only_input_errors(
        [&] { check(hmcr::read_json_file(cell, hmcr::sampling_cell_from_json)); });
    return 0;
}
