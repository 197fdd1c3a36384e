// SPDX-License-Identifier: Apache-2.0
// What a reference can judge (docs/design.md §6.10): the finest detail it resolves on each
// patch side, and the share of a solution's area in leaves finer than that.
//
// A mesh reference resolves its own elements: a leaf smaller than the reference's element there
// is compared with a field that is linear over the element, so the part of its error below the
// element's scale is invisible to it, and the study's error has a floor. A point reference has
// no such floor (its jittered points integrate any field without bias), but a leaf holding
// less than a point on average is measured with the quadrature's noise rather than its own
// detail. Either way a leaf counts as finer where its area is below half the reference's
// resolution on its side (one quadtree level or more below it).
#pragma once

#include <vector>

#include "radiosity/shaded_mesh.h"
#include "viz/point_radiosity_file.h"

namespace hmcr {

// The share of a cell's area in finer leaves above which a study warns (and --strict refuses).
inline constexpr double kFinerShareLimit = 0.1;

class ReferenceResolution {
public:
    ReferenceResolution() = default;
    // Per side: the largest element area of the reference there.
    static ReferenceResolution of_mesh(const ShadedMesh& reference);
    // Per side: its area per point (the points' mean weight there).
    static ReferenceResolution of_points(const PointRadiosity& points);

    bool empty() const { return m_area.empty(); }
    // The share of the solution's cell area whose element area is below half the resolution of
    // its side; a side the reference does not cover is not counted.
    double finer_share(const ShadedMesh& solution) const;

private:
    std::vector<double> m_area;  // m^2, by 2 * patch + side; 0 where the reference has nothing
};

}  // namespace hmcr
