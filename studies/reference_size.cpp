// SPDX-License-Identifier: Apache-2.0
#include "studies/reference_size.h"

#include <fmt/format.h>

#include <algorithm>

#include "rays/patch.h"
#include "studies/point_reference.h"

namespace hmcr {

ReferenceSize reference_size_for_budget(const Scene& scene, std::uint64_t budget) {
    const double area = build_patch_set(scene.mesh).total_area;
    ReferenceSize s;
    s.points = std::max(kDefaultReferencePoints, kPointsPerLeaf * budget);
    s.max_area = area / double(kElementsPerLeaf * budget);
    s.why = fmt::format(
        "{} points or {} uniform elements a leaf of the budget, of the scene's {:.4g} m^2",
        kPointsPerLeaf, kElementsPerLeaf, area);
    return s;
}

}  // namespace hmcr
