// SPDX-License-Identifier: Apache-2.0
// An object error as cell files, table.json and `hmcr error` write it (docs/design.md §11.7):
// {"relative_l2", "standard_error", "samples", "unmatched", "nearest", "unlit", "largest":
// [{"patch", "side", "share"}]}, non-finite numbers as null.
#pragma once

#include <nlohmann/json.hpp>

#include "studies/object_space_error.h"

namespace hmcr {

nlohmann::json object_error_json(const ObjectError& e);
// Checked as a cell file is (studies/table_fields.h): throws InputError on a negative error or
// a count that is not one; null is +inf where samples were taken, NaN (not measured) otherwise.
ObjectError object_error_from_json(const nlohmann::json& oe);

}  // namespace hmcr
