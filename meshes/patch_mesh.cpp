// SPDX-License-Identifier: Apache-2.0
#include "meshes/patch_mesh.h"

#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/hash.h"
#include "common/memory.h"

namespace hmcr {

FaceMaterials::FaceMaterials(const PatchMesh& mesh) : m_mesh(mesh) {
    OpenMesh::MPropHandleT<std::vector<FaceMaterial>> table;
    if (!mesh.get_property_handle(table, kMaterialsProp) ||
        !mesh.get_property_handle(m_index, kMaterialProp)) {
        throw std::invalid_argument("patch mesh has no material properties");
    }
    m_table = &mesh.property(table);
    m_has_back = mesh.get_property_handle(m_back, kBackMaterialProp);
}

std::uint32_t FaceMaterials::back_index(OpenMesh::FaceHandle f) const {
    if (!m_has_back) return kOneSided;
    const std::uint32_t m = m_mesh.property(m_back, f);
    if (m != kOneSided && m >= m_table->size()) {
        throw std::invalid_argument("face " + std::to_string(f.idx()) + " names back material " +
                                    std::to_string(m) + " of " + std::to_string(m_table->size()));
    }
    return m;
}

std::uint32_t FaceMaterials::index(OpenMesh::FaceHandle f) const {
    const std::uint32_t m = m_mesh.property(m_index, f);
    if (m >= m_table->size()) {
        throw std::invalid_argument("face " + std::to_string(f.idx()) + " names material " +
                                    std::to_string(m) + " of " + std::to_string(m_table->size()));
    }
    return m;
}

void set_face_material(PatchMesh& mesh, OpenMesh::FaceHandle f, const FaceMaterial& material) {
    std::vector<FaceMaterial>& table = *materials_prop(mesh);
    material_prop(mesh)[f] = std::uint32_t(table.size());
    table.push_back(material);
}

void release(PatchMesh& mesh) {
    mesh.clear();
    return_freed_memory();
}

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
