// Welding: exactly equal positions are one vertex. The builder (adjacency) and the repairs
// (repeated corners, duplicate faces) must agree on what "the same corner" means, so both use
// this one definition.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hmcr {

// id[k] of positions[k]: equal positions share an id; ids count up from 0 in order of first
// appearance. welded_count is the number of distinct positions.
std::vector<int> weld(const std::vector<Eigen::Vector3d>& positions, std::size_t& welded_count);

}  // namespace hmcr
