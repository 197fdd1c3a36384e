// SPDX-License-Identifier: Apache-2.0
#include "viz/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkTypeUInt64Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/atomic_file.h"
#include "common/error.h"
#include "image/tone_map.h"
#include "viz/mesh_colors.h"
#include "viz/vtk_console.h"
#include "viz/vtp_io.h"

#ifndef HMCR_VERSION
#error "HMCR_VERSION must be defined by the build"
#endif

namespace hmcr {
namespace {

// A VTK array over `values` without a copy (at a million patches the copies were 90 MB at the
// peak of the output). VTK's arrays take non-const storage; the writer only reads it, and the
// array is released with the polydata before write_vtp returns, while `values` still lives.
template <class Array, class T>
vtkNew<Array> view_array(const char* name, const std::vector<T>& values, int components = 1) {
    using Value = typename Array::ValueType;
    static_assert(sizeof(T) % sizeof(Value) == 0);
    vtkNew<Array> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    auto* data = const_cast<Value*>(reinterpret_cast<const Value*>(values.data()));
    a->SetArray(data, vtkIdType(values.size() * sizeof(T) / sizeof(Value)), /*save=*/1);
    return a;
}

// Cell ids below 2^31 as a 32-bit array.
vtkNew<vtkTypeInt32Array> narrowed_ids(const char* name, const std::vector<std::int64_t>& ids) {
    vtkNew<vtkTypeInt32Array> a;
    a->SetName(name);
    a->SetNumberOfTuples(vtkIdType(ids.size()));
    std::int32_t* out = a->GetPointer(0);
    for (std::size_t i = 0; i < ids.size(); ++i) out[i] = std::int32_t(ids[i]);
    return a;
}

vtkNew<vtkUnsignedCharArray> color_array(const ShadedMesh& mesh) {
    const auto colors = point_colors(mesh);
    vtkNew<vtkUnsignedCharArray> a;
    a->SetName("RadiosityColor");
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(vtkIdType(colors.size()));
    for (std::size_t i = 0; i < colors.size(); ++i) {
        for (int k = 0; k < 3; ++k) a->SetTypedComponent(vtkIdType(i), k, colors[i][k]);
    }
    return a;
}

void set_geometry(vtkPolyData* pd, const ShadedMesh& mesh) {
    static_assert(sizeof(Vec3) == 3 * sizeof(double));
    vtkNew<vtkPoints> points;
    points->SetData(view_array<vtkDoubleArray>("Points", mesh.points, 3));
    pd->SetPoints(points);
    vtkNew<vtkCellArray> polys;
    // 32-bit ids whenever they fit (every mesh that fits in memory): a fifth less to compress
    // and to read back than VTK's 64-bit default, the same cells.
    if (mesh.connectivity.size() <= std::size_t(std::numeric_limits<std::int32_t>::max())) {
        polys->SetData(narrowed_ids("offsets", mesh.offsets),
                       narrowed_ids("connectivity", mesh.connectivity));
    } else {
        polys->SetData(view_array<vtkTypeInt64Array>("offsets", mesh.offsets),
                       view_array<vtkTypeInt64Array>("connectivity", mesh.connectivity));
    }
    pd->SetPolys(polys);
}

void set_attributes(vtkPolyData* pd, const ShadedMesh& mesh) {
    pd->GetPointData()->AddArray(rgb_float_array("Radiosity", mesh.point_radiosity));
    pd->GetPointData()->SetScalars(color_array(mesh));
    vtkCellData* cd = pd->GetCellData();
    cd->AddArray(rgb_float_array("ElementRadiosity", mesh.element_radiosity));
    cd->AddArray(view_array<vtkIntArray>("HierarchyLevel", mesh.hierarchy_level));
    cd->AddArray(view_array<vtkIntArray>("PatchId", mesh.patch_id));
    cd->AddArray(view_array<vtkDoubleArray>("ElementArea", mesh.element_area));
    // Which side a cell shows: only in a solution with two-sided patches, so that a one-sided
    // scene's file is what it always was.
    const bool backs = std::find(mesh.side.begin(), mesh.side.end(), kBack) != mesh.side.end();
    if (backs) cd->AddArray(view_array<vtkUnsignedCharArray>("Side", mesh.side));
    if (!mesh.cluster_id.empty()) {
        cd->AddArray(view_array<vtkIntArray>("ClusterId", mesh.cluster_id));
    }
    // What evaluates a higher-order solution anywhere (docs/design.md §5.9): only on such a
    // basis, so that a constant solution's file is what it always was.
    if (mesh.basis != Basis::constant) {
        static_assert(sizeof(Vec2) == 2 * sizeof(double));
        pd->GetPointData()->AddArray(
            view_array<vtkDoubleArray>("LeafCoordinates", mesh.leaf_coordinates, 2));
        cd->AddArray(
            view_array<vtkDoubleArray>("Coefficients", mesh.coefficients, int(mesh.cell_stride())));
        cd->AddArray(view_array<vtkIntArray>("LeafIndex", mesh.leaf_index));
    }
}

void set_metadata(vtkPolyData* pd, const ShadedMesh& mesh, const VtpMetadata& meta) {
    vtkFieldData* fd = pd->GetFieldData();
    add_string_field(fd, "Oracle", meta.oracle);
    add_value_field<vtkDoubleArray>(fd, "Epsilon", meta.epsilon);
    add_value_field<vtkTypeUInt64Array>(fd, "Lines", meta.lines);
    add_value_field<vtkTypeUInt64Array>(fd, "Rays", meta.rays);
    add_value_field<vtkTypeUInt64Array>(fd, "Seed", meta.seed);
    add_value_field<vtkTypeUInt64Array>(fd, "ElementCount", meta.element_count);
    add_value_field<vtkTypeUInt64Array>(fd, "Iterations", meta.iterations);
    add_string_field(fd, "HmcrVersion", HMCR_VERSION);
    add_value_field<vtkDoubleArray>(fd, "TimeValue", meta.time_value);
    add_string_field(fd, "Scene", meta.scene);
    add_value_field<vtkTypeUInt64Array>(fd, "PatchCount", meta.patch_count);
    add_string_field(fd, "GeometryHash", meta.geometry_hash);
    add_string_field(fd, "LinkWeight", meta.link_weight);
    add_string_field(fd, "Clustering", meta.clustering);
    add_value_field<vtkTypeUInt64Array>(fd, "MeshLeaves", meta.mesh_leaves);
    if (mesh.basis != Basis::constant) {
        add_string_field(fd, "Basis", std::string(basis_name(mesh.basis)));
    }
}

}  // namespace

void write_vtp(const std::filesystem::path& path, const ShadedMesh& mesh, const VtpMetadata& meta) {
    silence_vtk_console();
    vtkNew<vtkPolyData> pd;
    set_geometry(pd, mesh);
    set_attributes(pd, mesh);
    set_metadata(pd, mesh, meta);
    write_file_atomically(path,
                          [&](const std::filesystem::path& tmp) { write_polydata(pd, tmp, path); });
}

}  // namespace hmcr
