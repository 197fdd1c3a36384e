// SPDX-License-Identifier: Apache-2.0
#include "meshes/material_sides.h"

#include <fmt/format.h>

#include <set>

namespace hmcr {
namespace {

using nlohmann::json;

int sides_value(const json& n, const std::string& where) {
    if (!n.is_number_integer() || (n.get<long long>() != 1 && n.get<long long>() != 2)) {
        throw InputError(where, "must be 1 or 2");
    }
    return n.get<int>();
}

}  // namespace

void apply_sides_keys(const json& j, const std::string& file, LoadOptions& options) {
    if (j.contains("sides")) {
        const int sides = sides_value(j["sides"], file + ": sides");
        if (!options.sides) options.sides = sides;
    }
    if (!j.contains("material_sides")) return;
    const std::string where = file + ": material_sides";
    const json& by_name = j["material_sides"];
    if (!by_name.is_object())
        throw InputError(where, "must be an object of material names and 1 or 2");
    options.material_sides.where = where;
    for (const auto& [name, n] : by_name.items()) {
        options.material_sides.by_name[name] =
            sides_value(n, fmt::format("{}: {}", where, quote(name)));
    }
}

void assign_sides(PolygonSoup& soup, const LoadOptions& options) {
    const std::map<std::string, int>& by_name = options.material_sides.by_name;
    std::set<std::string> named;
    std::vector<int> sides(soup.materials.size());
    for (std::size_t m = 0; m < soup.materials.size(); ++m) {
        const SoupMaterial& sm = soup.materials[m];
        const auto it = by_name.find(sm.material.name);
        if (it != by_name.end()) {
            sides[m] = it->second;
            named.insert(it->first);
        } else {
            sides[m] = options.sides.value_or(sm.sides != 0 ? sm.sides : kDefaultSides);
        }
    }
    for (const auto& entry : by_name) {
        if (named.count(entry.first) == 0) {
            throw InputError(options.material_sides.where,
                             fmt::format("no material {} in the mesh", quote(entry.first)));
        }
    }
    // A face without a material takes the default one, of the load's sides.
    const int unnamed = options.sides.value_or(kDefaultSides);
    for (std::size_t k = 0; k < soup.polygon_count(); ++k) {
        const std::int32_t m = soup.material[k];
        const int n = m == PolygonSoup::kNoMaterial ? unnamed : sides[std::size_t(m)];
        soup.back[k] = n == 2 ? m : PolygonSoup::kOneSided;
    }
}

}  // namespace hmcr
