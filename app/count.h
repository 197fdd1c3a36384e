// Counts on the command line (--rays, --lines, --budget, --seed, study budgets): 10000000, 1e7
// or 2.5e6, whole numbers only.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace hmcr {

// The count, or nothing for text that is not a whole number in range.
std::optional<std::uint64_t> parse_count(const std::string& text);
// The option check built on it (rewrites the text to plain digits for CLI11).
const CLI::Validator& count_notation();

}  // namespace hmcr
