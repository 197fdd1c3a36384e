// SPDX-License-Identifier: Apache-2.0
// Options that contradict each other are refused, saying why, rather than one silently winning.
#include <filesystem>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

// --rays-per-leaf sets every cell's rays: a --rays beside it was ignored without a word.
TEST_F(Hostile, RaysPerLeafWithRaysIsRefused) {
    plates();
    std::filesystem::create_directories(dir() / "ref");
    refused("study plates.json --reference ref -o st --budgets 20 --rays-per-leaf 100 --rays 1e6",
            "give --rays-per-leaf or --rays, not both: --rays-per-leaf sets every cell's rays");
}

}  // namespace
}  // namespace hmcr::test
