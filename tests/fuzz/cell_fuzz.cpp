// libFuzzer target: a study's cell files (cells/CELL.json), as a resumed study reads them.
#include <cstdint>

#include "common/text_file.h"
#include "studies/study.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const auto cell = write("cell.json", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        const hmcr::CellResult c = hmcr::read_json_file(
            cell, [](const nlohmann::json& j) { return hmcr::cell_from_json(j); });
        // What the tables then do with it must work too.
        (void)hmcr::cell_to_json(c).dump();
    });
    return 0;
}
