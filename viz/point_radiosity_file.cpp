// SPDX-License-Identifier: Apache-2.0
#include "viz/point_radiosity_file.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeUInt64Array.h>
#include <vtkUnsignedCharArray.h>

#include "common/atomic_file.h"
#include "viz/vtp_io.h"

namespace hmcr {
namespace {

constexpr const char* kNotPoints = "not an hmcr point reference";

vtkNew<vtkDoubleArray> rgb_double_array(const char* name, const std::vector<Rgb>& values) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(vtkIdType(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (int k = 0; k < 3; ++k) a->SetTypedComponent(vtkIdType(i), k, values[i][k]);
    }
    return a;
}

template <class Array, class F>
vtkNew<Array> per_point(const char* name, std::size_t n, F value) {
    vtkNew<Array> a;
    a->SetName(name);
    a->SetNumberOfTuples(vtkIdType(n));
    for (std::size_t i = 0; i < n; ++i) a->SetValue(vtkIdType(i), value(i));
    return a;
}

std::vector<Rgb> read_rgb(vtkPointData* pd, const char* name, vtkIdType n, double lowest,
                          const VtpChecker& check) {
    auto* a = check.array<vtkDoubleArray>(pd, name, 3, n, kNotPoints);
    std::vector<Rgb> out(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            out[std::size_t(i)][k] = check.finite_at_least(a->GetValue(3 * i + k), lowest, name);
        }
    }
    return out;
}

}  // namespace

void write_point_radiosity(const std::filesystem::path& path, const PointRadiosity& r) {
    const std::size_t n = r.points.size();
    vtkNew<vtkPolyData> pd;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(n));
    for (std::size_t i = 0; i < n; ++i) points->SetPoint(vtkIdType(i), r.points[i].position.data());
    pd->SetPoints(points);
    vtkNew<vtkCellArray> verts;
    for (std::size_t i = 0; i < n; ++i) {
        const vtkIdType id = vtkIdType(i);
        verts->InsertNextCell(1, &id);
    }
    pd->SetVerts(verts);
    vtkPointData* data = pd->GetPointData();
    data->AddArray(per_point<vtkIntArray>(
        "PatchId", n, [&](std::size_t i) { return std::int32_t(r.points[i].patch); }));
    data->AddArray(per_point<vtkUnsignedCharArray>(
        "Side", n, [&](std::size_t i) { return r.points[i].side; }));
    data->AddArray(
        per_point<vtkDoubleArray>("Weight", n, [&](std::size_t i) { return r.points[i].weight; }));
    std::vector<Rgb> mean(n);
    for (std::size_t i = 0; i < n; ++i) mean[i] = r.mean(i);
    data->SetScalars(rgb_float_array("Radiosity", mean));
    data->AddArray(rgb_double_array("Radiosity1", r.radiosity[0]));
    data->AddArray(rgb_double_array("Radiosity2", r.radiosity[1]));
    data->AddArray(rgb_double_array("Variance1", r.variance[0]));
    data->AddArray(rgb_double_array("Variance2", r.variance[1]));
    vtkFieldData* fd = pd->GetFieldData();
    add_string_field(fd, "Scene", r.scene);
    add_string_field(fd, "GeometryHash", r.geometry_hash);
    add_string_field(fd, "HmcrVersion", HMCR_VERSION);
    add_value_field<vtkTypeUInt64Array>(fd, "PatchCount", r.patch_count);
    add_value_field<vtkTypeUInt64Array>(fd, "Paths", r.paths);
    add_value_field<vtkTypeUInt64Array>(fd, "Seed", r.seed);
    write_file_atomically(path,
                          [&](const std::filesystem::path& tmp) { write_polydata(pd, tmp, path); });
}

PointRadiosity read_point_radiosity(const std::filesystem::path& path) {
    const VtpChecker check(path);
    const vtkSmartPointer<vtkPolyData> data = read_polydata(path, check);
    const vtkIdType n = data->GetNumberOfPoints();
    if (n < 1) check.fail("holds no points: not an hmcr point reference");
    if (data->GetNumberOfPolys() || data->GetNumberOfLines() || data->GetNumberOfStrips()) {
        check.fail("has cells that are not vertices: not an hmcr point reference");
    }
    PointRadiosity r;
    vtkFieldData* fd = data->GetFieldData();
    r.scene = check.string_field(fd, "Scene", kNotPoints);
    r.geometry_hash = check.string_field(fd, "GeometryHash", kNotPoints);
    r.patch_count = check.count_field(fd, "PatchCount", kNotPoints);
    r.paths = check.count_field(fd, "Paths", kNotPoints);
    r.seed = check.count_field(fd, "Seed", kNotPoints);
    if (r.paths < 1) check.fail("Paths is 0: every point needs a path");
    vtkPointData* pd = data->GetPointData();
    auto* patch = check.array<vtkIntArray>(pd, "PatchId", 1, n, kNotPoints);
    auto* side = check.array<vtkUnsignedCharArray>(pd, "Side", 1, n, kNotPoints);
    auto* weight = check.array<vtkDoubleArray>(pd, "Weight", 1, n, kNotPoints);
    r.points.resize(std::size_t(n));
    for (vtkIdType i = 0; i < n; ++i) {
        SurfacePoint& p = r.points[std::size_t(i)];
        const double* x = data->GetPoint(i);
        for (int k = 0; k < 3; ++k)
            p.position[k] = check.finite_at_least(x[k], -HUGE_VAL, "a point coordinate");
        const std::int32_t id = check.finite_at_least(patch->GetValue(i), 0, "PatchId");
        if (std::uint64_t(id) >= r.patch_count) {
            check.fail(fmt::format("point {} has PatchId {}, but the scene has {} patches", i, id,
                                   r.patch_count));
        }
        p.patch = std::uint32_t(id);
        const unsigned s = side->GetValue(i);
        if (s > kBack) check.fail(fmt::format("point {} has Side {}, not 0 or 1", i, s));
        p.side = std::uint8_t(s);
        p.weight = check.finite_at_least(weight->GetValue(i), 0.0, "Weight");
        if (!(p.weight > 0)) check.fail(fmt::format("point {} has Weight 0", i));
    }
    r.radiosity[0] = read_rgb(pd, "Radiosity1", n, 0.0, check);
    r.radiosity[1] = read_rgb(pd, "Radiosity2", n, 0.0, check);
    r.variance[0] = read_rgb(pd, "Variance1", n, 0.0, check);
    r.variance[1] = read_rgb(pd, "Variance2", n, 0.0, check);
    return r;
}

}  // namespace hmcr
