#include "viz/vtk_import.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <stdexcept>

#include "common/error.h"
#include <string>

namespace hmcr {
namespace {

vtkDataArray* require(vtkDataArray* a, const std::filesystem::path& path, const char* name) {
    if (!a) throw InputError(path.string(), std::string("not an hmcr solution (no ") + name + ")");
    return a;
}

}  // namespace

ShadedMesh read_vtp(const std::filesystem::path& path) {
    if (!std::filesystem::is_regular_file(path)) {
        throw InputError(path.string(), "no such file");
    }
    vtkObject::GlobalWarningDisplayOff();  // our one-line error says it; VTK's would be many
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkPolyData* data = reader->GetOutput();
    if (reader->GetErrorCode() != 0 || !data || data->GetNumberOfPoints() == 0) {
        throw InputError(path.string(), "cannot read it as VTK PolyData");
    }
    vtkDataArray* b = require(data->GetPointData()->GetArray("Radiosity"), path, "Radiosity");
    vtkDataArray* eb = require(data->GetCellData()->GetArray("ElementRadiosity"), path,
                               "ElementRadiosity");
    vtkDataArray* level = require(data->GetCellData()->GetArray("HierarchyLevel"), path,
                                  "HierarchyLevel");
    vtkDataArray* patch = require(data->GetCellData()->GetArray("PatchId"), path, "PatchId");
    vtkDataArray* area = require(data->GetCellData()->GetArray("ElementArea"), path,
                                 "ElementArea");
    ShadedMesh m;
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
        const double* p = data->GetPoint(i);
        m.points.emplace_back(p[0], p[1], p[2]);
        m.point_radiosity.emplace_back(b->GetComponent(i, 0), b->GetComponent(i, 1),
                                       b->GetComponent(i, 2));
    }
    auto ids = vtkSmartPointer<vtkIdList>::New();
    vtkCellArray* polys = data->GetPolys();
    polys->InitTraversal();
    for (vtkIdType c = 0; polys->GetNextCell(ids); ++c) {
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) m.connectivity.push_back(ids->GetId(k));
        m.offsets.push_back(std::int64_t(m.connectivity.size()));
        m.element_radiosity.emplace_back(eb->GetComponent(c, 0), eb->GetComponent(c, 1),
                                         eb->GetComponent(c, 2));
        m.hierarchy_level.push_back(int(level->GetComponent(c, 0)));
        m.patch_id.push_back(int(patch->GetComponent(c, 0)));
        m.element_area.push_back(area->GetComponent(c, 0));
    }
    return m;
}

}  // namespace hmcr
