#include "meshes/patch_mesh.h"

#include <bit>
#include <cstdint>

#include "common/hash.h"

namespace hmcr {

std::string geometry_hash(const PatchMesh& mesh) {
    Fnv1a h;
    h.add(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        h.add(mesh.valence(fh));
        for (const auto vh : mesh.fv_range(fh)) {
            const auto& p = mesh.point(vh);
            for (int k = 0; k < 3; ++k) h.add(std::bit_cast<std::uint64_t>(p[k] + 0.0));
        }
    }
    return h.hex();
}

}  // namespace hmcr
