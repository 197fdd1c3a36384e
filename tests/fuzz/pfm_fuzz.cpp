// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: PFM images, as a study reads a reference's views/VIEW.pfm.
#include <cstdint>

#include "image/image.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const auto pfm = write("view.pfm", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        const hmcr::Image image = hmcr::read_pfm(pfm);
        if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
            crash("pixel count is not width x height");
        }
    });
    return 0;
}
