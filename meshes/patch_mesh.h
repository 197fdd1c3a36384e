// SPDX-License-Identifier: Apache-2.0
// The patch mesh: every input polygon (triangle or planar convex quad) is one face of an
// OpenMesh PolyMesh; material data lives in named properties: a table of the mesh's materials
// and, per face, its index in the table (4 bytes a face instead of 48 for two colours: 44 MB
// at a million patches).
#pragma once

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <cstdint>
#include <string>
#include <vector>

namespace hmcr {

struct PatchMeshTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;  // metres
    using Normal = OpenMesh::Vec3d;
};
using PatchMesh = OpenMesh::PolyMesh_ArrayKernelT<PatchMeshTraits>;

struct FaceMaterial {
    OpenMesh::Vec3d reflectance{0, 0, 0};  // rho in [0, 1)
    OpenMesh::Vec3d emission{0, 0, 0};     // E = pi * Ke, W/m^2
    OpenMesh::Vec3d specular{0, 0, 0};     // Material::ks: the path tracer's alone
    double roughness = 0;                  // Material::roughness
};

// Names of the properties every loaded PatchMesh carries.
inline constexpr const char* kMaterialsProp = "hmcr:materials";     // mesh: vector<FaceMaterial>
inline constexpr const char* kMaterialProp = "hmcr:material";       // face: index into the table
inline constexpr const char* kSourceLineProp = "hmcr:source_line";  // face: 1-based, 0 = none
// face: the material of the face's back side, or kOneSided (the back is black and absorbing)
inline constexpr const char* kBackMaterialProp = "hmcr:back_material";
inline constexpr std::uint32_t kOneSided = 0xffffffff;

// Typed handles on those properties (they exist on every mesh the loaders return).
inline auto materials_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<void, std::vector<FaceMaterial>>(m, kMaterialsProp);
}
inline auto material_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<OpenMesh::FaceHandle, std::uint32_t>(m, kMaterialProp);
}
inline auto back_material_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<OpenMesh::FaceHandle, std::uint32_t>(m, kBackMaterialProp);
}
inline auto source_line_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<OpenMesh::FaceHandle, int>(m, kSourceLineProp);
}

// The faces' materials of a mesh, read through its table (both properties looked up once).
class FaceMaterials {
public:
    // Throws std::invalid_argument when the mesh lacks the properties.
    explicit FaceMaterials(const PatchMesh& mesh);
    // Throws std::invalid_argument when the face's index is not in the table.
    std::uint32_t index(OpenMesh::FaceHandle f) const;
    // The back side's index, or kOneSided (also for a mesh without the property).
    std::uint32_t back_index(OpenMesh::FaceHandle f) const;
    const FaceMaterial& operator[](OpenMesh::FaceHandle f) const { return (*m_table)[index(f)]; }
    const std::vector<FaceMaterial>& table() const { return *m_table; }

private:
    const PatchMesh& m_mesh;
    const std::vector<FaceMaterial>* m_table = nullptr;
    OpenMesh::FPropHandleT<std::uint32_t> m_index, m_back;
    bool m_has_back = false;
};

// Gives face f a material of its own, appended to the table (for meshes built by hand).
void set_face_material(PatchMesh& mesh, OpenMesh::FaceHandle f, const FaceMaterial& material);

// Empties the mesh and gives its memory back (for a caller that keeps what it needs of it).
void release(PatchMesh& mesh);

// A fingerprint of the patches' geometry (corner count and the exact bits of every corner, in
// face order): a solution records it, so that it is never read with another scene.
std::string geometry_hash(const PatchMesh& mesh);

}  // namespace hmcr
