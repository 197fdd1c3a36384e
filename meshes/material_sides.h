// SPDX-License-Identifier: Apache-2.0
// Which polygons have a back (docs/design.md §1.3): a polygon of a two-sided material gets a back
// of the same material. The sides of a material are the load's (LoadOptions::sides,
// material_sides), else its file's (MGF's `sides`), else kDefaultSides.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "meshes/polygon_soup.h"
#include "meshes/scene.h"

namespace hmcr {

// A scene file's "sides" (1 or 2; the command line's, already in `options`, wins) and
// "material_sides" ({"NAME": 1 or 2}) into `options`. Throws InputError "FILE: KEY: why".
void apply_sides_keys(const nlohmann::json& j, const std::string& file, LoadOptions& options);

// Sets soup.back for every polygon. Throws InputError at options.material_sides.where for a name
// no material of the soup has (a typo would otherwise change nothing, silently).
void assign_sides(PolygonSoup& soup, const LoadOptions& options);

}  // namespace hmcr
