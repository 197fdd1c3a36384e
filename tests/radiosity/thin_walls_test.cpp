// SPDX-License-Identifier: Apache-2.0
// A thin wall written as two faces of N corners facing away from each other solves as the same
// wall written as quads (docs/design.md §1.6): one surface with two sides, no light lost on
// backs, the same power on each side and the same escaped power, within the noise of the seeds.
#include "tests/support/thin_walls.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "meshes/scene.h"
#include "radiosity/solver.h"
#include "tests/support/plugins.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

// One solve's powers, W (channel 0): on the wall's paint (fronts), on its tiles (backs), and
// escaped.
struct WallPowers {
    double paint = 0, tiles = 0, escaped = 0, back_faces = 0;
};

WallPowers solve_wall(const std::filesystem::path& mgf, std::uint64_t seed) {
    const Scene scene = load_scene(mgf.string());
    SolverOptions o;
    o.oracle = oracle("power");
    o.rays = 100'000;
    o.seed = seed;
    const Solution sol = solve(scene.mesh, o);
    const Hierarchy& h = *sol.hierarchy;
    WallPowers w;
    for (std::size_t p = 2; p < h.patch_count(); ++p) {  // after the two lamps
        w.paint += h.root(p).radiosity[0] * h.root(p).area;
        if (const Element* back = h.back_root(p)) w.tiles += back->radiosity[0] * back->area;
    }
    w.escaped = sol.stats.escaped_power[0];
    w.back_faces = sol.stats.back_face_power[0];
    return w;
}

class ThinWalls : public testing::TestWithParam<int> {};

// Seeds 1-6 of each wall: the per-seed differences have mean 0 (a t test), and no shot power
// meets a back (the wall's faces are two-sided, the lamps face it).
TEST_P(ThinWalls, APolygonWallSolvesAsTheSameWallAsQuads) {
    const int corners = GetParam();
    TempDir dir;
    const auto polygon = dir.write("polygon.mgf", thin_wall_mgf(corners, WallFaces::polygon));
    const auto quads = dir.write("quads.mgf", thin_wall_mgf(corners, WallFaces::quads));
    std::vector<double> paint, tiles, escaped;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const WallPowers a = solve_wall(polygon, seed), b = solve_wall(quads, seed);
        EXPECT_EQ(a.back_faces, 0.0) << "seed " << seed;
        EXPECT_EQ(b.back_faces, 0.0) << "seed " << seed;
        paint.push_back(a.paint - b.paint);
        tiles.push_back(a.tiles - b.tiles);
        escaped.push_back(a.escaped - b.escaped);
    }
    EXPECT_TRUE(t_test("paint power, polygon - quads", paint, 0, 0, 3));
    EXPECT_TRUE(t_test("tile power, polygon - quads", tiles, 0, 0, 3));
    EXPECT_TRUE(t_test("escaped power, polygon - quads", escaped, 0, 0, 3));
}

INSTANTIATE_TEST_SUITE_P(Corners, ThinWalls, testing::Values(5, 8));

}  // namespace
}  // namespace hmcr::test
