// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a reference folder's reference.json, as `render --reference` and `study`
// read it (the exposure of every view).
#include <cmath>
#include <cstdint>

#include "common/file_names.h"
#include "studies/reference.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    write("reference.json", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        for (const auto& [view, exposure] : hmcr::read_reference_exposures(work_dir())) {
            if (!(exposure > 0 && std::isfinite(exposure)))
                crash("an exposure that is not positive");
            if (hmcr::name_problem(view)) crash("a view name that cannot name a file");
        }
    });
    return 0;
}
