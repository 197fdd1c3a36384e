// SPDX-License-Identifier: Apache-2.0
// Reading the members of a parsed JSON file (common/text_file.h) so that a missing member or one
// of the wrong type is said with its path from the top, "reference.views.side.exposure: must be a
// number, not a string", rather than in nlohmann's words, which name no key.
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace hmcr {

// The member reached from `j` through `keys`, each step an object; `path` names `j` itself
// ("" for the top). Throws InputError "PATH.KEY: missing" or "PATH: must be an object, not ...".
const nlohmann::json& json_member(const nlohmann::json& j,
                                  std::initializer_list<std::string_view> keys,
                                  const std::string& path = "");

// `path` joined with `key`: "reference.views" and "side" give "reference.views.side".
std::string json_path(const std::string& path, std::string_view key);

// Throws InputError "PATH: must be KIND, not TYPE" unless `j` is an object, a number, a string.
const nlohmann::json& json_object(const nlohmann::json& j, const std::string& path);
double json_number(const nlohmann::json& j, const std::string& path);
std::string json_string(const nlohmann::json& j, const std::string& path);

}  // namespace hmcr
