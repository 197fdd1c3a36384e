// SPDX-License-Identifier: Apache-2.0
// What the repairs did (meshes/repairs.h): each kind counted with the place of its first case,
// for the one summary line on stderr and the run summary's "repairs".
#pragma once

#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace hmcr {

enum class RepairKind {
    triangulated,        // more than 4 corners, or a concave quad: ear clipping
    quad_split,          // a non-planar quad: two triangles along the shorter diagonal
    corners_removed,     // repeated or collinear corners taken out of a face that stays
    degenerate_dropped,  // a face without area (fewer than 3 distinct, non-collinear corners)
    duplicate_dropped,   // the same corners in the same order and material as an earlier face
    reflectance_one,     // a material with Kd = 1 in a channel, accepted
    sides_joined,        // a face on an earlier one's corners facing the other way: its back
    coincident_dropped,  // a face on an earlier one's corners the same way, in another material
    specular_reduced,    // an MGF material's rs reduced so that rd + rs fits below 1
};
inline constexpr std::size_t kRepairKinds = 9;

struct RepairTally {
    std::size_t count = 0;
    std::string first;  // "file:line" of the first case
};

struct RepairReport {
    std::array<RepairTally, kRepairKinds> kinds;

    void add(RepairKind kind, const std::string& where);
    const RepairTally& operator[](RepairKind kind) const { return kinds[std::size_t(kind)]; }
    std::size_t total() const;
    bool empty() const { return total() == 0; }
    // "2 polygons triangulated (first at a.obj:12), 1 duplicate face dropped (a.obj:40)".
    std::string summary() const;
    // {"count": N, "KIND": {"count": n, "first": "file:line"}, ...}: only the kinds that occur.
    nlohmann::json to_json() const;
};

// The JSON key of a kind ("triangulated", "quads_split", ...).
const char* repair_key(RepairKind kind);

}  // namespace hmcr
