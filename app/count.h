// SPDX-License-Identifier: Apache-2.0
// Numbers on the command line: counts (--rays, --lines, --budget, --seed, study budgets:
// 10000000, 1e7 or 2.5e6, whole numbers only) and real numbers (finite, every one).
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

// Gives every real-valued option of `app` and of its subcommands (a CLI11 FLOAT, alone or in a
// list) the check that its text is a finite number: CLI11 reads "nan", "inf" and "1e309" (as
// infinity) as numbers, and no option of hmcr means them. Called once, after every command has
// added its options.
void require_finite_reals(CLI::App& app);

}  // namespace hmcr
