// SPDX-License-Identifier: Apache-2.0
// A meshing study's cell (studies/study.h) measured as its tables and plots show it: each image
// error averaged over the views, and NaN, left out of the means, where nothing was measured.
#pragma once

#include <limits>
#include <map>
#include <string>

#include "studies/study.h"

namespace hmcr {

inline double view_mean(const std::map<std::string, ImageErrors>& views,
                        double ImageErrors::*field) {
    double sum = 0;
    for (const auto& [name, e] : views) sum += e.*field;
    return views.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / double(views.size());
}

inline double view_mean(const CellResult& c, double ImageErrors::*field) {
    return view_mean(c.views, field);
}

// The frozen re-solve's errors.
inline double mesh_view_mean(const CellResult& c, double ImageErrors::*field) {
    return c.mesh_rays > 0 ? view_mean(c.mesh_views, field)
                           : std::numeric_limits<double>::quiet_NaN();
}

inline double mesh_object_error(const CellResult& c) {
    return c.mesh_rays > 0 ? c.mesh_object_error.relative_l2
                           : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace hmcr
