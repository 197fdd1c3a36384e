// SPDX-License-Identifier: Apache-2.0
// Welding: exactly equal positions are one vertex. The builder (adjacency) and the repairs
// (repeated corners, duplicate faces) must agree on what "the same corner" means, so both use
// this one definition.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hmcr {

struct Welding {
    std::vector<int> id;    // id[k] of positions[k]: equal positions share an id, counting up
                            // from 0 in order of first appearance
    std::size_t count = 0;  // the number of distinct positions
};
Welding weld(const std::vector<Eigen::Vector3d>& positions);

}  // namespace hmcr
