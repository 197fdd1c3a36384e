#include "meshes/weld.h"

#include <array>
#include <map>

namespace hmcr {

std::vector<int> weld(const std::vector<Eigen::Vector3d>& positions, std::size_t& welded_count) {
    std::map<std::array<double, 3>, int> index;
    std::vector<int> id(positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k) {
        const Eigen::Vector3d& p = positions[k];
        id[k] = index.try_emplace({p.x(), p.y(), p.z()}, int(index.size())).first->second;
    }
    welded_count = index.size();
    return id;
}

}  // namespace hmcr
