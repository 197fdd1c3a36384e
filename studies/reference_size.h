// SPDX-License-Identifier: Apache-2.0
// How large a reference a study needs (docs/studies.md, "Choosing a reference"): the sizes
// `hmcr reference --for-budget N` gives where the command line gives none.
#pragma once

#include <cstdint>
#include <string>

#include "meshes/scene.h"

namespace hmcr {

// Reference points per leaf of the largest budget, and uniform elements per leaf, chosen by
// measurement (docs/decisions.md, "Point references").
inline constexpr std::uint64_t kPointsPerLeaf = 20;
inline constexpr std::uint64_t kElementsPerLeaf = 16;

struct ReferenceSize {
    std::uint64_t points = 0;  // a point reference's --points
    double max_area = 0;       // a mesh reference's --max-area, m^2
    std::string why;           // one clause saying how they follow from the budget
};

ReferenceSize reference_size_for_budget(const Scene& scene, std::uint64_t budget);

}  // namespace hmcr
