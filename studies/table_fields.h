// How the study files write and read a field: CSV numbers and text, and JSON numbers that may
// be infinite or NaN (JSON has neither: nlohmann writes them as null).
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace hmcr {

// The number at `key`, or `missing` where it is null or absent.
inline double json_number(const nlohmann::json& j, const char* key, double missing) {
    const auto it = j.find(key);
    return it == j.end() || it->is_null() ? missing : it->get<double>();
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
