// SPDX-License-Identifier: Apache-2.0
#include "meshes/repair_report.h"

#include <fmt/format.h>

namespace hmcr {

void RepairReport::add(RepairKind kind, const std::string& where) {
    RepairTally& t = kinds[std::size_t(kind)];
    if (t.count++ == 0) t.first = where;
}

std::size_t RepairReport::total() const {
    std::size_t sum = 0;
    for (const RepairTally& t : kinds) sum += t.count;
    return sum;
}

const char* repair_key(RepairKind kind) {
    static constexpr const char* kKeys[kRepairKinds] = {
        "triangulated",       "quads_split",        "corners_removed",
        "degenerate_dropped", "duplicates_dropped", "reflectance_one",
        "sides_joined",       "coincident_dropped", "specular_reduced"};
    return kKeys[std::size_t(kind)];
}

std::string RepairReport::summary() const {
    static constexpr const char* kWhat[kRepairKinds][2] = {
        {"polygon triangulated", "polygons triangulated"},
        {"non-planar quad split", "non-planar quads split"},
        {"face with repeated or collinear corners simplified",
         "faces with repeated or collinear corners simplified"},
        {"degenerate face dropped", "degenerate faces dropped"},
        {"duplicate face dropped", "duplicate faces dropped"},
        {"material with reflectance 1 accepted", "materials with reflectance 1 accepted"},
        {"face facing away from a coincident one joined as its back side",
         "faces facing away from coincident ones joined as their back sides"},
        {"coincident face of another material dropped (the first kept)",
         "coincident faces of another material dropped (the first kept)"},
        {"material with rd + rs above 1 given a smaller rs",
         "materials with rd + rs above 1 given a smaller rs"}};
    std::string out;
    for (std::size_t k = 0; k < kRepairKinds; ++k) {
        const RepairTally& t = kinds[k];
        if (t.count == 0) continue;
        out +=
            fmt::format("{}{} {} ({}{})", out.empty() ? "" : ", ", t.count,
                        kWhat[k][t.count == 1 ? 0 : 1], t.count == 1 ? "" : "first at ", t.first);
    }
    return out;
}

nlohmann::json RepairReport::to_json() const {
    nlohmann::json out = {{"count", total()}};
    for (std::size_t k = 0; k < kRepairKinds; ++k) {
        if (kinds[k].count == 0) continue;
        out[repair_key(RepairKind(k))] = {{"count", kinds[k].count}, {"first", kinds[k].first}};
    }
    return out;
}

}  // namespace hmcr
