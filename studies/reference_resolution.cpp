// SPDX-License-Identifier: Apache-2.0
#include "studies/reference_resolution.h"

#include <algorithm>

#include "viz/shaded_tracer.h"

namespace hmcr {
namespace {

std::size_t key(std::uint32_t patch, std::uint8_t side) { return 2 * std::size_t(patch) + side; }

void grow(std::vector<double>& v, std::size_t k) {
    if (k >= v.size()) v.resize(k + 1, 0.0);
}

}  // namespace

ReferenceResolution ReferenceResolution::of_mesh(const ShadedMesh& reference) {
    ReferenceResolution r;
    for (std::size_t c = 0; c < reference.cell_count(); ++c) {
        const std::size_t k = key(std::uint32_t(reference.patch_id[c]), cell_side(reference, c));
        grow(r.m_area, k);
        r.m_area[k] = std::max(r.m_area[k], reference.element_area[c]);
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
    for (std::size_t c = 0; c < solution.cell_count(); ++c) {
        const std::size_t k = key(std::uint32_t(solution.patch_id[c]), cell_side(solution, c));
        if (k >= m_area.size() || !(m_area[k] > 0)) continue;
        const double a = solution.element_area[c];
        total += a;
        if (a < 0.5 * m_area[k]) finer += a;
    }
    return total > 0 ? finer / total : 0;
}

}  // namespace hmcr
