// SPDX-License-Identifier: Apache-2.0
// A point reference's points on disk (docs/design.md §11.10): VTK XML PolyData of vertices, one
// per quadrature point, which ParaView shows as a point cloud coloured by radiosity.
//
//   points           the points' positions (float64)
//   verts            one vertex cell per point
//   point data       PatchId (int32), Side (uint8: 0 front, 1 back), Weight (float64, m^2: the
//                    quadrature weight), Radiosity (float32 RGB: the two seeds' mean, to look at),
//                    Radiosity1, Radiosity2 (float64 RGB: each seed's estimate of B),
//                    Variance1, Variance2 (float64 RGB: the variance of each estimate)
//   field data       Scene, GeometryHash, HmcrVersion (strings), PatchCount, Paths (paths per
//                    point and seed), Seed (the first seed; the second is Seed + 1)
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/types.h"
#include "rays/surface_points.h"

namespace hmcr {

struct PointRadiosity {
    std::vector<SurfacePoint> points;
    // Per seed: each point's estimate of its radiosity B and the variance of that estimate.
    std::array<std::vector<Rgb>, 2> radiosity, variance;
    std::uint64_t paths = 0;  // per point and seed
    std::uint64_t seed = 1;   // the first; the second is seed + 1
    std::string scene, geometry_hash;
    std::uint64_t patch_count = 0;

    // The two seeds together: the mean of the estimates, and the variance of that mean.
    Rgb mean(std::size_t i) const { return 0.5 * (radiosity[0][i] + radiosity[1][i]); }
    Rgb mean_variance(std::size_t i) const { return 0.25 * (variance[0][i] + variance[1][i]); }
};

// Writes the file atomically; throws InputError naming it on failure, leaving none behind.
void write_point_radiosity(const std::filesystem::path& path, const PointRadiosity& r);

// Reads it back with every array, count and value checked (a PatchId beyond PatchCount, a Side
// other than 0 or 1, a weight that is not positive, a negative or non-finite variance or a
// non-finite radiosity): throws InputError naming the file.
PointRadiosity read_point_radiosity(const std::filesystem::path& path);

}  // namespace hmcr
