// SPDX-License-Identifier: Apache-2.0
#include "studies/reference_resolution.h"

#include <algorithm>
#include <vector>

#include "viz/shaded_tracer.h"

namespace hmcr {
namespace {

std::size_t key(std::uint32_t patch, std::uint8_t side) { return 2 * std::size_t(patch) + side; }

void grow(std::vector<double>& v, std::size_t k) {
    if (k >= v.size()) v.resize(k + 1, 0.0);
}

// Each cell's leaf's area: its own on the constant basis, the sum of its leaf's sub-cells' on a
// higher one (radiosity/polynomial_mesh.h), since resolution is the leaves'.
std::vector<double> leaf_areas(const ShadedMesh& mesh) {
    if (mesh.leaf_index.empty()) return mesh.element_area;
    std::vector<double> leaf(mesh.leaf_count(), 0.0), out(mesh.cell_count());
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
        leaf[std::size_t(mesh.leaf_index[c])] += mesh.element_area[c];
    }
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
        out[c] = leaf[std::size_t(mesh.leaf_index[c])];
    }
    return out;
}

}  // namespace

ReferenceResolution ReferenceResolution::of_mesh(const ShadedMesh& reference) {
    ReferenceResolution r;
    const std::vector<double> area = leaf_areas(reference);
    for (std::size_t c = 0; c < reference.cell_count(); ++c) {
        const std::size_t k = key(std::uint32_t(reference.patch_id[c]), cell_side(reference, c));
        grow(r.m_area, k);
        r.m_area[k] = std::max(r.m_area[k], area[c]);
    }
    return r;
}

ReferenceResolution ReferenceResolution::of_points(const PointRadiosity& points) {
    ReferenceResolution r;
    std::vector<double> count;
    for (const SurfacePoint& p : points.points) {
        const std::size_t k = key(p.patch, p.side);
        grow(r.m_area, k);
        grow(count, k);
        r.m_area[k] += p.weight;
        count[k] += 1;
    }
    for (std::size_t k = 0; k < r.m_area.size(); ++k) {
        if (count[k] > 0) r.m_area[k] /= count[k];
    }
    return r;
}

double ReferenceResolution::finer_share(const ShadedMesh& solution) const {
    double finer = 0, total = 0;
    const std::vector<double> leaf = leaf_areas(solution);
    for (std::size_t c = 0; c < solution.cell_count(); ++c) {
        const std::size_t k = key(std::uint32_t(solution.patch_id[c]), cell_side(solution, c));
        if (k >= m_area.size() || !(m_area[k] > 0)) continue;
        const double a = solution.element_area[c];
        total += a;
        if (leaf[c] < 0.5 * m_area[k]) finer += a;
    }
    return total > 0 ? finer / total : 0;
}

}  // namespace hmcr
