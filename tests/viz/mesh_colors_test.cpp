// SPDX-License-Identifier: Apache-2.0
#include "viz/mesh_colors.h"

#include <gtest/gtest.h>

#include <numbers>

#include "image/image.h"  // Srgb8

namespace hmcr {
namespace {

// Two grey cells: B = 0.1 pi on area 1 and 0.3 pi on area 3, so the mean radiance is 0.25.
ShadedMesh two_cells() {
    ShadedMesh m;
    m.element_radiosity = {Rgb::Constant(0.1 * std::numbers::pi),
                           Rgb::Constant(0.3 * std::numbers::pi)};
    m.element_area = {1, 3};
    m.point_radiosity = {Rgb::Constant(0.25 * std::numbers::pi), Rgb::Zero(),
                         Rgb(0.25 * std::numbers::pi / 0.2126, 0, 0)};
    m.points.resize(3, Vec3::Zero());
    return m;
}

TEST(MeshColors, ExposureMapsMeanLuminanceToMiddleGrey) {
    EXPECT_DOUBLE_EQ(auto_exposure(two_cells()), 0.18 / 0.25);
    ShadedMesh black = two_cells();
    black.element_radiosity.assign(2, Rgb::Zero());
    EXPECT_EQ(auto_exposure(black), 1);
    EXPECT_EQ(auto_exposure(ShadedMesh{}), 1);
}

TEST(MeshColors, PointColorsUseTheMeshExposure) {
    const auto colors = point_colors(two_cells());
    ASSERT_EQ(colors.size(), 3u);
    EXPECT_EQ(colors[0], (Srgb8{118, 118, 118}));  // the mean radiance becomes middle grey
    EXPECT_EQ(colors[1], (Srgb8{0, 0, 0}));
    EXPECT_EQ(colors[2], (Srgb8{237, 0, 0}));  // linear 0.18 / 0.2126 = 0.847 of red
}

}  // namespace
}  // namespace hmcr
