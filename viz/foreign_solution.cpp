// SPDX-License-Identifier: Apache-2.0
#include "viz/foreign_solution.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include "viz/vtk_import.h"
#include "viz/vtp_io.h"

namespace hmcr {
namespace {

constexpr const char* kNotASolution = "not a solution hmcr can measure";

// The array `name` of one of the given VTK data types, with `components` components and
// `tuples` tuples.
vtkDataArray* typed_array(vtkFieldData* data, const char* name, std::initializer_list<int> types,
                          int components, vtkIdType tuples, const VtpChecker& check) {
    vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetAbstractArray(name));
    if (!a) check.fail(fmt::format("{} (no numeric {} array)", kNotASolution, name));
    if (std::find(types.begin(), types.end(), a->GetDataType()) == types.end()) {
        check.fail(fmt::format("array {} has type {}", name, a->GetDataTypeAsString()));
    }
    if (a->GetNumberOfComponents() != components || a->GetNumberOfTuples() != tuples) {
        check.fail(fmt::format("array {} has {} tuples of {} components; expected {} of {}", name,
                               a->GetNumberOfTuples(), a->GetNumberOfComponents(), tuples,
                               components));
    }
    return a;
}

double polygon_area(const ShadedMesh& m, std::size_t c) {
    Vec3 sum = Vec3::Zero();
    const auto first = m.offsets[c], last = m.offsets[c + 1];
    for (auto s = first; s < last; ++s) {
        const auto next = s + 1 < last ? s + 1 : first;
        sum += m.points[m.connectivity[s]].cross(m.points[m.connectivity[next]]);
    }
    return 0.5 * sum.norm();
}

}  // namespace

ShadedMesh read_foreign_solution(const std::filesystem::path& path, std::uint64_t patch_count) {
    const VtpChecker check(path);
    const vtkSmartPointer<vtkPolyData> data = read_polydata(path, check);
    if (data->GetNumberOfPoints() < 3 || data->GetNumberOfPolys() < 1) {
        check.fail(fmt::format("holds no polygons: {}", kNotASolution));
    }
    ShadedMesh m;
    const vtkIdType n = data->GetNumberOfPoints();
    vtkDataArray* b =
        typed_array(data->GetPointData(), "Radiosity", {VTK_FLOAT, VTK_DOUBLE}, 3, n, check);
    for (vtkIdType i = 0; i < n; ++i) {
        const double* p = data->GetPoint(i);
        for (int k = 0; k < 3; ++k) check.finite_at_least(p[k], -HUGE_VAL, "a point coordinate");
        m.points.emplace_back(p[0], p[1], p[2]);
        Rgb r;
        for (int k = 0; k < 3; ++k)
            r[k] = check.finite_at_least(b->GetComponent(i, k), 0.0, "Radiosity");
        m.point_radiosity.push_back(r);
    }
    read_polygon_cells(data, check, m);
    const vtkIdType cells = vtkIdType(m.cell_count());
    vtkCellData* cd = data->GetCellData();
    vtkDataArray* patch =
        typed_array(cd, "PatchId", {VTK_INT, VTK_LONG, VTK_LONG_LONG}, 1, cells, check);
    vtkDataArray* side =
        cd->HasArray("Side")
            ? typed_array(cd, "Side", {VTK_UNSIGNED_CHAR, VTK_INT}, 1, cells, check)
            : nullptr;
    for (vtkIdType c = 0; c < cells; ++c) {
        const double id = patch->GetComponent(c, 0);
        if (!(id >= 0 && double(id) < double(patch_count))) {
            check.fail(fmt::format("cell {} has PatchId {}, but the scene has {} patches", c, id,
                                   patch_count));
        }
        m.patch_id.push_back(int(id));
        const double s = side ? side->GetComponent(c, 0) : 0;
        if (s != kFront && s != kBack)
            check.fail(fmt::format("cell {} has Side {}, not 0 or 1", c, s));
        m.side.push_back(std::uint8_t(s));
        Rgb mean = Rgb::Zero();
        const auto first = m.offsets[std::size_t(c)], last = m.offsets[std::size_t(c) + 1];
        for (auto k = first; k < last; ++k) mean += m.point_radiosity[m.connectivity[k]];
        m.element_radiosity.emplace_back(mean / double(last - first));
        m.element_area.push_back(polygon_area(m, std::size_t(c)));
        m.hierarchy_level.push_back(0);
    }
    return m;
}

}  // namespace hmcr
