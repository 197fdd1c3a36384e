// SPDX-License-Identifier: Apache-2.0
#include "viz/vtk_export.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <csignal>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "common/atomic_file.h"
#include "tests/support/shaded_scenes.h"
#include "tests/support/temp_dir.h"
#include "viz/mesh_colors.h"

namespace hmcr::test {
namespace {

VtpMetadata sample_metadata() {
    VtpMetadata meta;
    meta.oracle = "ebs";
    meta.epsilon = 0.125;
    meta.lines = 1234567890123ull;
    meta.rays = 42;
    meta.seed = 0xFFFFFFFFFFFFFFF0ull;
    meta.element_count = 21;
    meta.iterations = 7;
    meta.time_value = 3.5;
    return meta;
}

// Floor and wall at a right angle, split unevenly, with a gradient on the floor.
MeshHierarchy sample_scene() {
    MeshHierarchy s(two_quads(false));
    s.at(0, {1, 2});
    s.at(1, {3});
    s.for_leaves(0, [&](Element& e) { e.radiosity = Rgb(1, 2, 3) * e.centre.y(); });
    s.for_leaves(1, [&](Element& e) { e.radiosity = Rgb(0.5, 0.25, 4); });
    return s;
}

vtkSmartPointer<vtkPolyData> read_with_vtk(const std::filesystem::path& path) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
}

void expect_array(vtkAbstractArray* a, int type, int components, bool rgb_names) {
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->GetDataType(), type) << a->GetName();
    EXPECT_EQ(a->GetNumberOfComponents(), components) << a->GetName();
    if (!rgb_names) return;
    for (int k = 0; k < 3; ++k) {
        ASSERT_NE(a->GetComponentName(k), nullptr);
        EXPECT_STREQ(a->GetComponentName(k), std::string(1, "RGB"[k]).c_str());
    }
}

class VtkExport : public testing::Test {
protected:
    TempDir m_dir;
    MeshHierarchy m_scene = sample_scene();
    ShadedMesh m_mesh = m_scene.shade();
};

TEST_F(VtkExport, WritesGeometryAndArraysOfSpec) {
    const auto path = m_dir.path() / "out" / "scene.vtp";
    write_vtp(path, m_mesh, sample_metadata());
    EXPECT_EQ(m_dir.files(), std::vector<std::string>{"out/scene.vtp"});  // no temp file left
    const auto pd = read_with_vtk(path);
    ASSERT_EQ(pd->GetNumberOfPoints(), vtkIdType(m_mesh.points.size()));
    ASSERT_EQ(pd->GetNumberOfCells(), vtkIdType(m_scene.h->leaf_count()));
    ASSERT_EQ(pd->GetNumberOfPolys(), vtkIdType(m_mesh.cell_count()));

    vtkPointData* point = pd->GetPointData();
    expect_array(point->GetAbstractArray("Radiosity"), VTK_FLOAT, 3, true);
    expect_array(point->GetAbstractArray("RadiosityColor"), VTK_UNSIGNED_CHAR, 3, false);
    ASSERT_NE(point->GetScalars(), nullptr);
    EXPECT_STREQ(point->GetScalars()->GetName(), "RadiosityColor");
    vtkCellData* cell = pd->GetCellData();
    expect_array(cell->GetAbstractArray("ElementRadiosity"), VTK_FLOAT, 3, true);
    expect_array(cell->GetAbstractArray("HierarchyLevel"), VTK_INT, 1, false);
    expect_array(cell->GetAbstractArray("PatchId"), VTK_INT, 1, false);
    expect_array(cell->GetAbstractArray("ElementArea"), VTK_DOUBLE, 1, false);
}

TEST_F(VtkExport, ValuesRoundTrip) {
    const auto path = m_dir.path() / "scene.vtp";
    write_vtp(path, m_mesh, sample_metadata());
    const auto pd = read_with_vtk(path);
    const auto colors = point_colors(m_mesh);
    vtkDataArray* radiosity = pd->GetPointData()->GetArray("Radiosity");
    vtkDataArray* color = pd->GetPointData()->GetArray("RadiosityColor");
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i) {
        EXPECT_TRUE(Vec3(pd->GetPoint(i)).isApprox(m_mesh.points[i]));
        for (int k = 0; k < 3; ++k) {
            EXPECT_FLOAT_EQ(radiosity->GetComponent(i, k), float(m_mesh.point_radiosity[i][k]));
            EXPECT_EQ(color->GetComponent(i, k), colors[i][k]);
        }
    }
    vtkDataArray* element = pd->GetCellData()->GetArray("ElementRadiosity");
    vtkDataArray* level = pd->GetCellData()->GetArray("HierarchyLevel");
    vtkDataArray* patch = pd->GetCellData()->GetArray("PatchId");
    vtkDataArray* area = pd->GetCellData()->GetArray("ElementArea");
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c) {
        EXPECT_FLOAT_EQ(element->GetComponent(c, 2), float(m_mesh.element_radiosity[c][2]));
        EXPECT_EQ(level->GetTuple1(c), m_mesh.hierarchy_level[c]);
        EXPECT_EQ(patch->GetTuple1(c), m_mesh.patch_id[c]);
        EXPECT_EQ(area->GetTuple1(c), m_mesh.element_area[c]);
        pd->GetPolys()->GetCellAtId(c, ids);
        ASSERT_EQ(ids->GetNumberOfIds(), m_mesh.offsets[c + 1] - m_mesh.offsets[c]);
        for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
            EXPECT_EQ(ids->GetId(i), m_mesh.connectivity[m_mesh.offsets[c] + i]);
        }
    }
}

TEST_F(VtkExport, FieldDataHoldsRunDescription) {
    const auto path = m_dir.path() / "scene.vtp";
    write_vtp(path, m_mesh, sample_metadata());
    const auto pd = read_with_vtk(path);
    vtkFieldData* fd = pd->GetFieldData();
    auto string_value = [&](const char* name) {
        auto* a = vtkStringArray::SafeDownCast(fd->GetAbstractArray(name));
        EXPECT_NE(a, nullptr) << name;
        return a && a->GetNumberOfValues() == 1 ? a->GetValue(0) : std::string("?");
    };
    EXPECT_EQ(string_value("Oracle"), "ebs");
    EXPECT_EQ(string_value("HmcrVersion"), HMCR_VERSION);
    auto number = [&](const char* name) {
        vtkAbstractArray* a = fd->GetAbstractArray(name);
        EXPECT_NE(a, nullptr) << name;
        EXPECT_EQ(a ? a->GetNumberOfTuples() : 0, 1) << name;
        return a ? a->GetVariantValue(0) : vtkVariant();
    };
    EXPECT_EQ(number("Epsilon").ToDouble(), 0.125);
    EXPECT_EQ(number("Lines").ToUnsignedLongLong(), 1234567890123ull);
    EXPECT_EQ(number("Rays").ToUnsignedLongLong(), 42u);
    EXPECT_EQ(number("Seed").ToUnsignedLongLong(), 0xFFFFFFFFFFFFFFF0ull);
    EXPECT_EQ(number("ElementCount").ToUnsignedLongLong(), 21u);
    EXPECT_EQ(number("Iterations").ToUnsignedLongLong(), 7u);
    EXPECT_EQ(number("TimeValue").ToDouble(), 3.5);
    EXPECT_EQ(fd->GetAbstractArray("TimeValue")->GetDataType(), VTK_DOUBLE);
}

TEST_F(VtkExport, FileIsAppendedRawAndCompressed) {
    const auto path = m_dir.path() / "scene.vtp";
    write_vtp(path, m_mesh, sample_metadata());
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("compressor=\"vtkLZ4DataCompressor\""), std::string::npos);
    EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
    // The cells' ids in 32 bits, which every mesh that fits in memory needs.
    EXPECT_NE(text.find("type=\"Int32\" Name=\"connectivity\""), std::string::npos);
    EXPECT_NE(text.find("type=\"Int32\" Name=\"offsets\""), std::string::npos);
}

TEST_F(VtkExport, ImpossiblePathThrowsAndLeavesNothing) {
    write_text_atomically(m_dir.path() / "file", "x");
    const auto below_file = m_dir.path() / "file" / "scene.vtp";
    try {
        write_vtp(below_file, m_mesh, sample_metadata());
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("scene.vtp"), std::string::npos) << e.what();
    }
    // A directory in the way: VTK writes the temp file, the rename fails.
    std::filesystem::create_directories(m_dir.path() / "taken" / "inside");
    EXPECT_THROW(write_vtp(m_dir.path() / "taken", m_mesh, sample_metadata()), std::runtime_error);
    EXPECT_EQ(m_dir.files(), std::vector<std::string>{"file"});
}

// A disk that fills as VTK writes: a file size limit of 200 bytes (the write then fails with
// EFBIG instead of raising SIGXFSZ, which is ignored for the while).
TEST_F(VtkExport, WriterFailureThrowsAndLeavesNothing) {
    const auto path = m_dir.path() / "full.vtp";
    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 200;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    try {
        write_vtp(path, m_mesh, sample_metadata());
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write " + path.string()), std::string::npos)
            << e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);
    EXPECT_TRUE(m_dir.files().empty());
}

}  // namespace
}  // namespace hmcr::test
