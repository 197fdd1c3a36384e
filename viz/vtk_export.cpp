#include "viz/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkTypeUInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "common/atomic_file.h"
#include "common/error.h"
#include "image/tone_map.h"
#include "viz/mesh_colors.h"
#include "viz/vtk_console.h"

#ifndef HMCR_VERSION
#error "HMCR_VERSION must be defined by the build"
#endif

namespace hmcr {
namespace {

// Collects VTK error messages instead of letting them go to the console.
class ErrorObserver : public vtkCommand {
public:
    static ErrorObserver* New() { return new ErrorObserver; }
    void Execute(vtkObject*, unsigned long, void* data) override {
        std::string text = data ? static_cast<const char*>(data) : "unknown VTK error";
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
            text.pop_back();
        }
        m_message += (m_message.empty() ? "" : "; ") + text;
    }
    const std::string& message() const { return m_message; }

private:
    std::string m_message;
};

vtkNew<vtkFloatArray> rgb_array(const char* name, const std::vector<Rgb>& values) {
    vtkNew<vtkFloatArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetComponentName(0, "R");
    a->SetComponentName(1, "G");
    a->SetComponentName(2, "B");
    a->SetNumberOfTuples(vtkIdType(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (int k = 0; k < 3; ++k) a->SetTypedComponent(vtkIdType(i), k, float(values[i][k]));
    }
    return a;
}

template <class Array, class T>
vtkNew<Array> scalar_array(const char* name, const std::vector<T>& values) {
    vtkNew<Array> a;
    a->SetName(name);
    a->SetNumberOfTuples(vtkIdType(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) a->SetValue(vtkIdType(i), values[i]);
    return a;
}

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
    pd->GetPointData()->AddArray(rgb_array("Radiosity", mesh.point_radiosity));
    pd->GetPointData()->SetScalars(color_array(mesh));
    vtkCellData* cd = pd->GetCellData();
    cd->AddArray(rgb_array("ElementRadiosity", mesh.element_radiosity));
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
}

void add_string(vtkFieldData* fd, const char* name, const std::string& value) {
    vtkNew<vtkStringArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
}

template <class Array, class T>
void add_value(vtkFieldData* fd, const char* name, T value) {
    fd->AddArray(scalar_array<Array>(name, std::vector<T>{value}));
}

void set_metadata(vtkPolyData* pd, const VtpMetadata& meta) {
    vtkFieldData* fd = pd->GetFieldData();
    add_string(fd, "Oracle", meta.oracle);
    add_value<vtkDoubleArray>(fd, "Epsilon", meta.epsilon);
    add_value<vtkTypeUInt64Array>(fd, "Lines", meta.lines);
    add_value<vtkTypeUInt64Array>(fd, "Rays", meta.rays);
    add_value<vtkTypeUInt64Array>(fd, "Seed", meta.seed);
    add_value<vtkTypeUInt64Array>(fd, "ElementCount", meta.element_count);
    add_value<vtkTypeUInt64Array>(fd, "Iterations", meta.iterations);
    add_string(fd, "HmcrVersion", HMCR_VERSION);
    add_value<vtkDoubleArray>(fd, "TimeValue", meta.time_value);
    add_string(fd, "Scene", meta.scene);
    add_value<vtkTypeUInt64Array>(fd, "PatchCount", meta.patch_count);
    add_string(fd, "GeometryHash", meta.geometry_hash);
    add_string(fd, "LinkWeight", meta.link_weight);
    add_string(fd, "Clustering", meta.clustering);
    add_value<vtkTypeUInt64Array>(fd, "MeshLeaves", meta.mesh_leaves);
}

void write_polydata(vtkPolyData* pd, const std::filesystem::path& file,
                    const std::filesystem::path& target) {
    vtkNew<vtkXMLPolyDataWriter> writer;
    vtkNew<ErrorObserver> errors, pipeline;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    // The executive repeats the failure with a dump of the request: keep it off the console.
    writer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipeline);
    writer->SetFileName(file.c_str());
    writer->SetInputData(pd);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    // LZ4, not zlib: several times faster to write and to read for a larger file, and every
    // ParaView and VTK reader decompresses it (docs/decisions.md). VTK's level 9 is LZ4's
    // default acceleration, its smallest fast mode.
    writer->SetCompressorTypeToLZ4();
    writer->SetCompressionLevel(9);
    const int ok = writer->Write();
    if (ok != 1 || writer->GetErrorCode() != 0 || !errors->message().empty() ||
        !pipeline->message().empty()) {
        // VTK's own text names its source file and line; say it in hmcr's words.
        const unsigned long code = writer->GetErrorCode();
        throw InputError("cannot write " + target.string(),
                         code != 0 ? std::string(vtkErrorCode::GetStringFromErrorCode(code))
                                   : "the VTK writer failed");
    }
}

}  // namespace

void write_vtp(const std::filesystem::path& path, const ShadedMesh& mesh, const VtpMetadata& meta) {
    silence_vtk_console();
    vtkNew<vtkPolyData> pd;
    set_geometry(pd, mesh);
    set_attributes(pd, mesh);
    set_metadata(pd, meta);
    write_file_atomically(path,
                          [&](const std::filesystem::path& tmp) { write_polydata(pd, tmp, path); });
}

}  // namespace hmcr
