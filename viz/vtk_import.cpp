// SPDX-License-Identifier: Apache-2.0
#include "viz/vtk_import.h"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
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
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "radiosity/basis.h"
#include "radiosity/solver_options.h"
#include "viz/vtp_io.h"

namespace hmcr {
namespace {

namespace fs = std::filesystem;

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

// The cells run as the leaves of docs/design.md §5.3: every patch's front, patch by patch, then
// the backs that exist, patch by patch. A Side array of a solution with backs that says all 0,
// all 1 or is shuffled, or cells of another order, are not an hmcr solution's.
void check_cell_order(const ShadedMesh& m, const VtpChecker& check, std::uint64_t patch_count) {
    std::uint64_t front_patches = 0;  // patches 0 .. front_patches - 1 have front cells
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
        const std::uint64_t patch = std::uint64_t(m.patch_id[c]);
        if (m.side[c] == kFront) {
            if (c > 0 && m.side[c - 1] == kBack) {
                check.fail(
                    fmt::format("cell {} is a front after a back: a solution's fronts come "
                                "first (is its Side array another's?)",
                                c));
            }
            if (patch > front_patches) {
                check.fail(fmt::format("patch {} has no front cell before cell {} (patch {}'s)",
                                       front_patches, c, patch));
            }
            if (patch + 1 < front_patches) {
                check.fail(
                    fmt::format("cell {} is patch {}'s front after patch {}'s: a "
                                "solution's cells run patch by patch",
                                c, patch, front_patches - 1));
            }
            front_patches = patch + 1;
        } else if (c > 0 && m.side[c - 1] == kBack && patch < std::uint64_t(m.patch_id[c - 1])) {
            check.fail(
                fmt::format("cell {} is patch {}'s back after patch {}'s: a solution's "
                            "cells run patch by patch",
                            c, patch, m.patch_id[c - 1]));
        }
    }
    if (front_patches < patch_count) {
        check.fail(
            fmt::format("patch {} has no front cell (of {} patches)", front_patches, patch_count));
    }
}

// ClusterId, only in a clustered solution: per cell the cluster leaf holding its side
// (docs/design.md §2.7), -1 where the side is in the mesh itself. A tree over the sides of P
// patches has fewer than 2 P - 1 clusters; every cell of one side names the same one.
void read_cluster_ids(vtkCellData* cd, const VtpChecker& check, const VtpMetadata& meta,
                      ShadedMesh& m) {
    if (!cd->HasArray("ClusterId")) return;
    if (meta.clustering == "none") {
        check.fail(fmt::format("has a ClusterId array, but Clustering {}", quote(meta.clustering)));
    }
    const vtkIdType n = vtkIdType(m.cell_count());
    auto* ids = check.array<vtkIntArray>(cd, "ClusterId", 1, n);
    const std::int64_t clusters = 2 * std::int64_t(meta.patch_count) - 1;
    m.cluster_id.resize(std::size_t(n));
    for (vtkIdType c = 0; c < n; ++c) {
        const int id = ids->GetValue(c);
        if (id < -1 || id >= clusters) {
            check.fail(
                fmt::format("cell {} has ClusterId {}, not -1 or one of the {} clusters "
                            "of {} patches",
                            c, id, std::max<std::int64_t>(clusters, 0), meta.patch_count));
        }
        const std::size_t k = std::size_t(c);
        if (k > 0 && m.patch_id[k] == m.patch_id[k - 1] && m.side[k] == m.side[k - 1] &&
            id != m.cluster_id[k - 1]) {
            check.fail(
                fmt::format("cell {} has ClusterId {}, the cell before it {}: one side of "
                            "a patch is in one cluster",
                            c, id, m.cluster_id[k - 1]));
        }
        m.cluster_id[k] = id;
    }
}

// The higher-order arrays (docs/design.md §5.9), all of them exactly when the Basis field names
// a basis other than the constant; a file without it is a constant solution's. The cells of one
// leaf run together, numbered from 0 in their order, one patch's side each, and every cell is
// a sub-square or a sub-triangle, whose basis its point count says.
void read_basis(vtkPolyData* data, const VtpChecker& check, ShadedMesh& m) {
    vtkFieldData* fd = data->GetFieldData();
    vtkPointData* pd = data->GetPointData();
    vtkCellData* cd = data->GetCellData();
    m.basis = Basis::constant;
    if (fd->HasArray("Basis")) {
        const std::string given = check.string_field(fd, "Basis", "not an hmcr solution");
        const auto known = std::find(kBasisNames.begin(), kBasisNames.end(), given);
        if (known == kBasisNames.end()) {
            check.fail(fmt::format(
                "has Basis {}, not constant, linear, bilinear, quadratic or cubic", quote(given)));
        }
        m.basis = Basis(known - kBasisNames.begin());
    }
    if (m.basis == Basis::constant) {
        for (const char* array : {"Coefficients", "LeafIndex"}) {
            if (cd->HasArray(array)) {
                check.fail(fmt::format("has a {} array, but no Basis beyond the constant", array));
            }
        }
        if (pd->HasArray("LeafCoordinates")) {
            check.fail("has a LeafCoordinates array, but no Basis beyond the constant");
        }
        return;
    }
    const vtkIdType points = vtkIdType(m.points.size()), cells = vtkIdType(m.cell_count());
    const std::string missing =
        fmt::format("not a whole solution on the {} basis", basis_name(m.basis));
    auto* ab = check.array<vtkDoubleArray>(pd, "LeafCoordinates", 2, points, missing.c_str());
    m.leaf_coordinates.resize(std::size_t(points));
    for (vtkIdType i = 0; i < points; ++i) {
        for (int k = 0; k < 2; ++k) {
            const double x = ab->GetValue(2 * i + k);
            if (!(x >= 0 && x <= 1)) {
                check.fail(fmt::format("point {} has LeafCoordinates {}, not in [0, 1]", i, x));
            }
            m.leaf_coordinates[std::size_t(i)][k] = x;
        }
    }
    const int stride = int(m.cell_stride());
    auto* coefficients =
        check.array<vtkDoubleArray>(cd, "Coefficients", stride, cells, missing.c_str());
    m.coefficients.resize(std::size_t(stride) * std::size_t(cells));
    for (std::size_t k = 0; k < m.coefficients.size(); ++k) {
        m.coefficients[k] = check.finite_at_least<double>(coefficients->GetValue(vtkIdType(k)),
                                                          -HUGE_VAL, "Coefficients");
    }
    auto* leaf = check.array<vtkIntArray>(cd, "LeafIndex", 1, cells, missing.c_str());
    m.leaf_index.resize(std::size_t(cells));
    for (std::size_t c = 0; c < std::size_t(cells); ++c) {
        const int corners = int(m.offsets[c + 1] - m.offsets[c]);
        if (corners != 3 && corners != 4) {
            check.fail(
                fmt::format("cell {} has {} points: a sub-cell of a leaf on the {} basis "
                            "is a triangle or a quad",
                            c, corners, basis_name(m.basis)));
        }
        const int id = leaf->GetValue(vtkIdType(c));
        const int previous = c == 0 ? -1 : m.leaf_index[c - 1];
        if (id != previous && id != previous + 1) {
            check.fail(
                fmt::format("cell {} has LeafIndex {} after {}: the cells of a leaf run "
                            "together, the leaves numbered from 0",
                            c, id, previous));
        }
        if (c > 0 && id == previous &&
            (m.patch_id[c] != m.patch_id[c - 1] || m.side[c] != m.side[c - 1])) {
            check.fail(
                fmt::format("cell {} has LeafIndex {}, as the cell before it, on another "
                            "patch or side",
                            c, id));
        }
        m.leaf_index[c] = id;
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
    if (cd->HasArray("Side")) {
        auto* side = check.array<vtkUnsignedCharArray>(cd, "Side", 1, n);
        for (vtkIdType c = 0; c < n; ++c) {
            const unsigned value = side->GetValue(c);
            if (value > kBack) check.fail(fmt::format("cell {} has Side {}, not 0 or 1", c, value));
            m.side[std::size_t(c)] = std::uint8_t(value);
        }
    }
    check_cell_order(m, check, patch_count);
}

template <class A>
auto value_field(vtkFieldData* fd, const char* name, const VtpChecker& check) {
    return check.array<A>(fd, name, 1, 1)->GetValue(0);
}

constexpr const char* kOldSolution = "not a solution of this version of hmcr (solve again)";

VtpMetadata read_metadata(vtkPolyData* data, const VtpChecker& check) {
    vtkFieldData* fd = data->GetFieldData();
    VtpMetadata meta;
    meta.scene = check.string_field(fd, "Scene", kOldSolution);
    meta.geometry_hash = check.string_field(fd, "GeometryHash", kOldSolution);
    meta.oracle = check.string_field(fd, "Oracle", kOldSolution);
    meta.patch_count = check.count_field(fd, "PatchCount");
    meta.epsilon = value_field<vtkDoubleArray>(fd, "Epsilon", check);
    meta.lines = check.count_field(fd, "Lines");
    meta.rays = check.count_field(fd, "Rays");
    meta.seed = check.count_field(fd, "Seed");
    meta.element_count = check.count_field(fd, "ElementCount");
    meta.iterations = check.count_field(fd, "Iterations");
    meta.time_value = value_field<vtkDoubleArray>(fd, "TimeValue", check);
    meta.clustering = check.string_field(fd, "Clustering", kOldSolution);
    if (!SettingNames<Clustering>::parse(meta.clustering)) {
        check.fail(fmt::format("has Clustering {}, not none, isotropic or oriented",
                               quote(meta.clustering)));
    }
    return meta;
}

}  // namespace

void read_polygon_cells(vtkPolyData* data, const VtpChecker& check, ShadedMesh& m) {
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

ShadedMesh read_vtp(const fs::path& path, VtpMetadata* metadata) {
    const VtpChecker check(path);
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
    read_polygon_cells(data, check, m);
    read_cell_data(data, check, meta.patch_count, m);
    read_cluster_ids(data->GetCellData(), check, meta, m);
    read_basis(data, check, m);
    if (m.leaf_index.empty() && m.cell_count() != meta.element_count) {
        check.fail(fmt::format("has {} cells but records {} elements", m.cell_count(),
                               meta.element_count));
    }
    if (!m.leaf_index.empty() && m.leaf_count() != meta.element_count) {
        check.fail(fmt::format("has {} leaves but records {} elements", m.leaf_count(),
                               meta.element_count));
    }
    if (metadata) *metadata = meta;
    return m;
}

}  // namespace hmcr
