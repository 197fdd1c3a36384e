// SPDX-License-Identifier: Apache-2.0
#include "app/count.h"

#include <cmath>
#include <cstdlib>

#include "common/types.h"

namespace hmcr {

std::optional<std::uint64_t> parse_count(const std::string& text) {
    std::size_t used = 0;
    double value = 0;
    // Plain digits are read exactly (up to 2^64 - 1); notation like 1e7 up to 2^53, where
    // doubles are exact.
    const bool plain = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    try {
        if (plain) return std::stoull(text);
        value = std::stod(text, &used);
    } catch (const std::exception&) {  // out of range, or not a number at all
        return std::nullopt;
    }
    if (used != text.size() || !(value >= 0) || value > 0x1p53 || value != std::floor(value)) {
        return std::nullopt;
    }
    return std::uint64_t(value);
}

const CLI::Validator& count_notation() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            const auto count = parse_count(text);
            if (!count) return "'" + text + "' is not a whole number in range";
            text = std::to_string(*count);
            return {};
        },
        "COUNT");
    return validator;
}

namespace {

const CLI::Validator& finite_number() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
            if (!std::isfinite(v)) return "'" + text + "' is not a finite number";
            return is_subnormal(v) ? "'" + text + "' " + kSubnormalReason : std::string();
        },
        "");
    return validator;
}

}  // namespace

void require_finite_reals(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        if (option->get_type_name().rfind("FLOAT", 0) == 0) option->check(finite_number());
    }
    for (CLI::App* command : app.get_subcommands({})) require_finite_reals(*command);
}

}  // namespace hmcr
