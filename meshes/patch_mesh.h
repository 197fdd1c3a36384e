// The patch mesh: every input polygon (triangle or planar convex quad) is one face of an
// OpenMesh PolyMesh; material data lives in named face properties.
#pragma once

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Utils/PropertyManager.hh>

#include <string>

namespace hmcr {

struct PatchMeshTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;   // metres
    using Normal = OpenMesh::Vec3d;
};
using PatchMesh = OpenMesh::PolyMesh_ArrayKernelT<PatchMeshTraits>;

// Names of the face properties every loaded PatchMesh carries.
inline constexpr const char* kReflectanceProp = "hmcr:reflectance";  // Vec3d, rho in [0, 1)
inline constexpr const char* kEmissionProp = "hmcr:emission";        // Vec3d, E = pi * Ke, W/m^2
inline constexpr const char* kSourceLineProp = "hmcr:source_line";   // int, 1-based, 0 = none

// Typed handles on those properties (they exist on every mesh the loaders return).
inline auto reflectance_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<OpenMesh::FaceHandle, OpenMesh::Vec3d>(m, kReflectanceProp);
}
inline auto emission_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<OpenMesh::FaceHandle, OpenMesh::Vec3d>(m, kEmissionProp);
}
inline auto source_line_prop(PatchMesh& m) {
    return OpenMesh::getOrMakeProperty<OpenMesh::FaceHandle, int>(m, kSourceLineProp);
}

// A fingerprint of the patches' geometry (corner count and the exact bits of every corner, in
// face order): a solution records it, so that it is never read with another scene.
std::string geometry_hash(const PatchMesh& mesh);

}  // namespace hmcr
