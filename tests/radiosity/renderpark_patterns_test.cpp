// SPDX-License-Identifier: Apache-2.0
// RenderPark's MGF scenes (rpkCpp's etc/, which hmcr's repository does not hold) load and solve:
// tests/data/mgf-patterns/ holds small scenes of hmcr's own that write what made four of them
// fail, each as its scene writes it (docs/renderpark-scenes.md): a hospital's touching wall
// boxes, included furniture in arrays, a library of materials and a red rd under a white rs; a
// luminaire mirrored by an array; an office's faces written twice in two materials; a
// classroom's bench top of two materials and materials defined again. Each loads with the
// repairs named and solves, and the light reaches the back sides (docs/design.md §1.3).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshes/scene.h"
#include "radiosity/solver.h"
#include "tests/support/plugins.h"

namespace hmcr::test {
namespace {

struct Pattern {
    const char* file;
    std::size_t patches, two_sided;
    std::size_t sides_joined, coincident_dropped, duplicates_dropped, specular_reduced;
};

std::filesystem::path pattern_path(const char* file) {
    return std::filesystem::path(HMCR_TEST_DATA) / "mgf-patterns" / file;
}

// The light on the back sides, W: the sum over back roots of radiosity x area.
double back_power(const Hierarchy& h) {
    double sum = 0;
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        if (const Element* r = h.back_root(p)) sum += r->radiosity.sum() * r->area;
    }
    return sum;
}

class RenderParkPatterns : public testing::TestWithParam<Pattern> {};

TEST_P(RenderParkPatterns, LoadsWithItsRepairsAndSolves) {
    const Pattern& p = GetParam();
    const Scene scene = load_scene(pattern_path(p.file).string());
    EXPECT_EQ(scene.mesh.n_faces(), p.patches);
    const RepairReport& r = scene.repairs;
    EXPECT_EQ(r[RepairKind::sides_joined].count, p.sides_joined);
    EXPECT_EQ(r[RepairKind::coincident_dropped].count, p.coincident_dropped);
    EXPECT_EQ(r[RepairKind::duplicate_dropped].count, p.duplicates_dropped);
    EXPECT_EQ(r[RepairKind::specular_reduced].count, p.specular_reduced);

    SolverOptions options;
    options.oracle = oracle("power");
    options.rays = 20'000;
    options.seed = 3;
    const Solution sol = solve(scene.mesh, options);
    EXPECT_EQ(sol.stats.two_sided_patches, p.two_sided);
    EXPECT_GT(sol.stats.leaves, 0u);
    EXPECT_GT(back_power(*sol.hierarchy), 0.0);
    if (p.two_sided == p.patches) {
        EXPECT_EQ(sol.stats.back_face_power.sum(), 0.0);
    }
}

// patches, two-sided, sides joined, coincident dropped, duplicates dropped, rs reduced
INSTANTIATE_TEST_SUITE_P(Scenes, RenderParkPatterns,
                         testing::Values(Pattern{"hospital-walls.mgf", 78, 78, 1, 0, 0, 1},
                                         Pattern{"examp1-reflector.mgf", 34, 27, 1, 0, 0, 0},
                                         Pattern{"graz-desks.mgf", 5, 5, 0, 1, 1, 0},
                                         Pattern{"classroom-benches.mgf", 4, 4, 1, 0, 1, 0}),
                         [](const testing::TestParamInfo<Pattern>& param) {
                             std::string name = param.param.file;
                             name = name.substr(0, name.find('.'));
                             std::erase(name, '-');
                             return name;
                         });

}  // namespace
}  // namespace hmcr::test
