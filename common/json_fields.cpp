// SPDX-License-Identifier: Apache-2.0
#include "common/json_fields.h"

#include <fmt/format.h>

#include "common/error.h"

namespace hmcr {
namespace {

[[noreturn]] void wrong_type(const nlohmann::json& j, const std::string& path, const char* kind) {
    throw InputError(path.empty() ? "the file" : path,
                     fmt::format("must be {}, not {}", kind, j.type_name()));
}

}  // namespace

std::string json_path(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

const nlohmann::json& json_object(const nlohmann::json& j, const std::string& path) {
    if (!j.is_object()) wrong_type(j, path, "an object");
    return j;
}

double json_number(const nlohmann::json& j, const std::string& path) {
    if (!j.is_number()) wrong_type(j, path, "a number");
    return j.get<double>();
}

std::string json_string(const nlohmann::json& j, const std::string& path) {
    if (!j.is_string()) wrong_type(j, path, "a string");
    return j.get<std::string>();
}

const nlohmann::json& json_member(const nlohmann::json& j,
                                  std::initializer_list<std::string_view> keys,
                                  const std::string& path) {
    const nlohmann::json* at = &j;
    std::string where = path;
    for (std::string_view key : keys) {
        const auto it = json_object(*at, where).find(key);
        where = json_path(where, key);
        if (it == at->end()) throw InputError(where, "missing");
        at = &*it;
    }
    return *at;
}

}  // namespace hmcr
