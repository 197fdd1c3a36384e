#include "viz/vtk_import.h"

#include <fmt/format.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>

#include "common/error.h"
#include "viz/vtk_console.h"
#include "viz/vtp_envelope.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

// Every array, count and cell is checked before use: a .vtp comes from outside, and VTK hands
// out whatever the file says (a 1-component "Radiosity", a PatchId of -7, lines for cells).
class VtpChecker {
public:
    explicit VtpChecker(const fs::path& path) : m_path(path.string()) {}

    [[noreturn]] void fail(const std::string& why) const { throw InputError(m_path, why); }

    // The array called name in `data`, of type A, with `components` components and `tuples`
    // tuples.
    template <class A>
    A* array(vtkFieldData* data, const char* name, int components, vtkIdType tuples) const {
        vtkAbstractArray* raw = data->GetAbstractArray(name);
        if (!raw) fail(fmt::format("not an hmcr solution (no {} array)", name));
        A* a = A::SafeDownCast(raw);
        if (!a) {
            const vtkNew<A> wanted;  // an instance only for its type's name
            fail(fmt::format("array {} has type {}, not {}", name, raw->GetDataTypeAsString(),
                             wanted->GetDataTypeAsString()));
        }
        if (a->GetNumberOfComponents() != components || a->GetNumberOfTuples() != tuples) {
            fail(fmt::format("array {} has {} tuples of {} components; expected {} of {}", name,
                             a->GetNumberOfTuples(), a->GetNumberOfComponents(), tuples,
                             components));
        }
        return a;
    }

    template <class T>
    T finite_at_least(T value, T lowest, const char* what) const {
        if (!(std::isfinite(double(value)) && value >= lowest)) {
            fail(fmt::format("{} {} is not a finite number of at least {}", what, value, lowest));
        }
        return value;
    }

private:
    std::string m_path;
};

// Reads the XML with VTK's own messages kept off the console: our one line says it.
vtkSmartPointer<vtkPolyData> read_polydata(const fs::path& path, const VtpChecker& check) {
    silence_vtk_console();
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    bool failed = false;
    auto on_error = vtkSmartPointer<vtkCallbackCommand>::New();
    on_error->SetClientData(&failed);
    on_error->SetCallback(
        [](vtkObject*, unsigned long, void* flag, void*) { *static_cast<bool*>(flag) = true; });
    reader->AddObserver(vtkCommand::ErrorEvent, on_error);
    reader->AddObserver(vtkCommand::WarningEvent, on_error);
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
    if (failed || reader->GetErrorCode() != 0 || !data)
        check.fail("cannot read it as VTK PolyData");
    return data;
}

void read_points(vtkPolyData* data, const VtpChecker& check, ShadedMesh& m) {
    const vtkIdType n = data->GetNumberOfPoints();
    auto* b = check.array<vtkFloatArray>(data->GetPointData(), "Radiosity", 3, n);
    for (vtkIdType i = 0; i < n; ++i) {
        const double* p = data->GetPoint(i);
        for (int k = 0; k < 3; ++k) check.finite_at_least(p[k], -HUGE_VAL, "a point coordinate");
        m.points.emplace_back(p[0], p[1], p[2]);
        Rgb r;
        // Negative where a signed estimator (the control variate, design.md §3.11) undershoots.
        for (int k = 0; k < 3; ++k)
            r[k] = check.finite_at_least<double>(b->GetValue(3 * i + k), -HUGE_VAL, "Radiosity");
        m.point_radiosity.push_back(r);
    }
}

void read_cells(vtkPolyData* data, const VtpChecker& check, ShadedMesh& m) {
    const vtkIdType points = data->GetNumberOfPoints();
    auto ids = vtkSmartPointer<vtkIdList>::New();
    vtkCellArray* polys = data->GetPolys();
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
        polys->GetCellAtId(c, ids);
        if (ids->GetNumberOfIds() < 3)
            check.fail(fmt::format("cell {} has fewer than 3 points", c));
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
            const vtkIdType id = ids->GetId(k);
            if (id < 0 || id >= points)
                check.fail(fmt::format("cell {} names point {} of {}", c, id, points));
            m.connectivity.push_back(id);
        }
        m.offsets.push_back(std::int64_t(m.connectivity.size()));
    }
}

void read_cell_data(vtkPolyData* data, const VtpChecker& check, std::uint64_t patch_count,
                    ShadedMesh& m) {
    const vtkIdType n = vtkIdType(m.cell_count());
    vtkCellData* cd = data->GetCellData();
    auto* eb = check.array<vtkFloatArray>(cd, "ElementRadiosity", 3, n);
    auto* level = check.array<vtkIntArray>(cd, "HierarchyLevel", 1, n);
    auto* patch = check.array<vtkIntArray>(cd, "PatchId", 1, n);
    auto* area = check.array<vtkDoubleArray>(cd, "ElementArea", 1, n);
    for (vtkIdType c = 0; c < n; ++c) {
        Rgb r;
        for (int k = 0; k < 3; ++k) {
            r[k] = check.finite_at_least<double>(eb->GetValue(3 * c + k), -HUGE_VAL,
                                                 "ElementRadiosity");
        }
        m.element_radiosity.push_back(r);
        m.hierarchy_level.push_back(check.finite_at_least(level->GetValue(c), 0, "HierarchyLevel"));
        const int p = check.finite_at_least(patch->GetValue(c), 0, "PatchId");
        if (std::uint64_t(p) >= patch_count) {
            check.fail(fmt::format("cell {} has PatchId {}, but the scene has {} patches", c, p,
                                   patch_count));
        }
        m.patch_id.push_back(p);
        m.element_area.push_back(check.finite_at_least(area->GetValue(c), 0.0, "ElementArea"));
    }
    // Side: present only in a solution with two-sided patches; every cell is a front without it.
    m.side.assign(std::size_t(n), kFront);
    if (!cd->HasArray("Side")) return;
    auto* side = check.array<vtkUnsignedCharArray>(cd, "Side", 1, n);
    for (vtkIdType c = 0; c < n; ++c) {
        const unsigned value = side->GetValue(c);
        if (value > kBack) check.fail(fmt::format("cell {} has Side {}, not 0 or 1", c, value));
        m.side[std::size_t(c)] = std::uint8_t(value);
    }
}

std::string string_field(vtkFieldData* fd, const char* name, const VtpChecker& check) {
    auto* a = vtkStringArray::SafeDownCast(fd->GetAbstractArray(name));
    if (!a || a->GetNumberOfValues() != 1) {
        check.fail(
            fmt::format("no {} field: not a solution of this version of hmcr (solve again)", name));
    }
    return a->GetValue(0);
}

template <class A>
auto value_field(vtkFieldData* fd, const char* name, const VtpChecker& check) {
    return check.array<A>(fd, name, 1, 1)->GetValue(0);
}

// A 64-bit unsigned field: VTK reads UInt64 back as its own unsigned long type, so the check is
// on the data type, not the array class.
std::uint64_t count_field(vtkFieldData* fd, const char* name, const VtpChecker& check) {
    vtkAbstractArray* a = fd->GetAbstractArray(name);
    if (!a) check.fail(fmt::format("not an hmcr solution (no {} field)", name));
    const int type = a->GetDataType();
    const bool unsigned64 =
        (type == VTK_UNSIGNED_LONG || type == VTK_UNSIGNED_LONG_LONG) && a->GetDataTypeSize() == 8;
    if (!unsigned64 || a->GetNumberOfComponents() != 1 || a->GetNumberOfTuples() != 1) {
        check.fail(fmt::format("field {} is not one unsigned 64-bit count", name));
    }
    return a->GetVariantValue(0).ToTypeUInt64();
}

VtpMetadata read_metadata(vtkPolyData* data, const VtpChecker& check) {
    vtkFieldData* fd = data->GetFieldData();
    VtpMetadata meta;
    meta.scene = string_field(fd, "Scene", check);
    meta.geometry_hash = string_field(fd, "GeometryHash", check);
    meta.oracle = string_field(fd, "Oracle", check);
    meta.patch_count = count_field(fd, "PatchCount", check);
    meta.epsilon = value_field<vtkDoubleArray>(fd, "Epsilon", check);
    meta.lines = count_field(fd, "Lines", check);
    meta.rays = count_field(fd, "Rays", check);
    meta.seed = count_field(fd, "Seed", check);
    meta.element_count = count_field(fd, "ElementCount", check);
    meta.iterations = count_field(fd, "Iterations", check);
    meta.time_value = value_field<vtkDoubleArray>(fd, "TimeValue", check);
    return meta;
}

}  // namespace

ShadedMesh read_vtp(const fs::path& path, VtpMetadata* metadata) {
    const VtpChecker check(path);
    std::error_code ec;
    if (!fs::exists(path, ec)) check.fail("no such file");
    if (!fs::is_regular_file(path, ec)) check.fail("is not a regular file");
    check_vtp_envelope(path);
    const vtkSmartPointer<vtkPolyData> data = read_polydata(path, check);
    if (data->GetNumberOfVerts() || data->GetNumberOfLines() || data->GetNumberOfStrips()) {
        check.fail("has cells that are not polygons (vertices, lines or strips)");
    }
    if (data->GetNumberOfPoints() < 3 || data->GetNumberOfPolys() < 1) {
        check.fail("holds no polygons: not an hmcr solution");
    }
    const VtpMetadata meta = read_metadata(data, check);
    ShadedMesh m;
    read_points(data, check, m);
    read_cells(data, check, m);
    read_cell_data(data, check, meta.patch_count, m);
    if (m.cell_count() != meta.element_count) {
        check.fail(fmt::format("has {} cells but records {} elements", m.cell_count(),
                               meta.element_count));
    }
    if (metadata) *metadata = meta;
    return m;
}

}  // namespace hmcr
