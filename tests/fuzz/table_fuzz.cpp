// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a study's table.json, as `hmcr plot` reads it (either kind of study).
#include <cstdint>

#include "studies/plot_data.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const auto table = write("table.json", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        const nlohmann::json plots = hmcr::plot_data_of_table(table);
        // What `hmcr plot` then writes for the plotting script must serialise.
        (void)plots.dump();
        for (const auto& figure : plots.at("figures")) {
            for (const auto& panel : figure.at("panels")) {
                if (panel.contains("series") && panel.at("series").size() > 64) {
                    crash("more series than names a study can hold");
                }
            }
        }
    });
    return 0;
}
