// SPDX-License-Identifier: Apache-2.0
// How the study files write and read a field: CSV numbers and text, and JSON numbers that may
// be infinite or NaN (JSON has neither: nlohmann writes them as null). A cell file is checked as
// it is read: a count that is negative or not whole, an error or a time below zero, is an
// InputError, and the study computes the cell again.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "common/error.h"

namespace hmcr {

// A value not measured (or a failed cell's), written as null in JSON and empty in CSV.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The number at `key`, or `missing` where it is null or absent.
inline double json_number(const nlohmann::json& j, const char* key, double missing) {
    const auto it = j.find(key);
    return it == j.end() || it->is_null() ? missing : it->get<double>();
}

// json_number of a quantity that cannot be negative (an error, a PSNR, a time); NaN passes.
inline double json_non_negative(const nlohmann::json& j, const char* key, double missing) {
    const double x = json_number(j, key, missing);
    if (x < 0) throw InputError(fmt::format("{}: {} is negative", key, x));
    return x;
}

// The count at `key`: a whole JSON number from 0 to `max` (nlohmann alone would read -3 as
// 2^64 - 3).
inline std::uint64_t json_count(const nlohmann::json& j, const char* key,
                                std::uint64_t max = std::numeric_limits<std::uint64_t>::max()) {
    const nlohmann::json& value = j.at(key);
    if (!value.is_number_unsigned()) {
        throw InputError(fmt::format("{}: {} is not a count", key, quote(value.dump())));
    }
    if (value.get<std::uint64_t>() > max) {
        throw InputError(
            fmt::format("{}: {} is more than {}", key, value.get<std::uint64_t>(), max));
    }
    return value.get<std::uint64_t>();
}

// A cell's status: "ok" or "failed".
inline std::string json_status(const nlohmann::json& j) {
    std::string status = j.at("status").get<std::string>();
    if (status != "ok" && status != "failed") {
        throw InputError("status: " + quote(status) + " is neither \"ok\" nor \"failed\"");
    }
    return status;
}

// A finite number, or null (JSON has no NaN or infinity; stored as null in memory too, so that a
// cell read back compares equal to the one written).
inline nlohmann::json json_finite_or_null(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

// NaN is an empty field; infinities are "inf" and "-inf".
inline std::string csv_number(double x) {
    if (std::isnan(x)) return "";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return fmt::format("{}", x);
}

// Quoted only when it holds a comma, a quote or a line break (RFC 4180).
inline std::string csv_text(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

}  // namespace hmcr
