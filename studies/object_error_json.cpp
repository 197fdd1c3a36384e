// SPDX-License-Identifier: Apache-2.0
#include "studies/object_error_json.h"

#include <limits>

#include "studies/table_fields.h"

namespace hmcr {

nlohmann::json object_error_json(const ObjectError& e) {
    nlohmann::json largest = nlohmann::json::array();
    for (const PatchError& p : e.largest) {
        largest.push_back({{"patch", p.patch}, {"side", p.side}, {"share", p.share}});
    }
    return {{"relative_l2", e.relative_l2},
            {"standard_error", json_finite_or_null(e.standard_error)},
            {"samples", e.samples},
            {"unmatched", e.unmatched},
            {"nearest", e.nearest},
            {"unlit", e.unlit},
            {"largest", largest}};
}

// null: +inf (only B_ref is 0) when measured, NaN when not (a traced reference has no mesh).
ObjectError object_error_from_json(const nlohmann::json& oe) {
    ObjectError e;
    e.samples = json_count(oe, "samples");
    e.relative_l2 = json_non_negative(
        oe, "relative_l2", e.samples > 0 ? std::numeric_limits<double>::infinity() : kNaN);
    e.standard_error = json_non_negative(oe, "standard_error", kNaN);
    e.unmatched = json_count(oe, "unmatched", e.samples);
    e.nearest = oe.contains("nearest") ? json_count(oe, "nearest", e.samples) : 0;
    e.unlit = oe.contains("unlit") ? json_count(oe, "unlit", e.samples) : 0;
    // Absent from the cells of a version that did not list them.
    const auto listed = oe.find("largest");
    for (const nlohmann::json& p : listed == oe.end() ? nlohmann::json::array() : *listed) {
        const std::uint64_t side = json_count(p, "side", kBack);
        e.largest.push_back({std::uint32_t(json_count(p, "patch", 0xffffffffULL)),
                             std::uint8_t(side), json_number(p, "share", kNaN)});
    }
    return e;
}

}  // namespace hmcr
