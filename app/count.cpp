#include "app/count.h"

#include <cmath>

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

}  // namespace hmcr
