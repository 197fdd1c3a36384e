// SPDX-License-Identifier: Apache-2.0
// The library's common path (library/hmcr.h) is the layers' own calls: what `hmcr solve` writes,
// and what `hmcr error` measures of that file.
#include "library/hmcr.h"

#include <gtest/gtest.h>

#include "common/output_set.h"
#include "rays/patch.h"
#include "studies/reference.h"
#include "tests/support/temp_dir.h"
#include "viz/solution_file.h"

namespace hmcr::test {
namespace {

TEST(Library, SolvesWritesAndMeasuresAsTheCommandsDo) {
    const TempDir dir;
    const Scene scene = load("plates");
    SolverOptions options = settings_of(scene);
    EXPECT_EQ(options.rays, 1'000'000u);  // the scene file's "solver" object
    options.rays = 20'000;
    const Solution solution = solve(scene, options);
    // The solve `hmcr solve plates --rays 20000` makes: from the patches, with the scene's views.
    const Solution direct = solve(build_patch_set(scene.mesh), options, SolveInputs{scene.views});
    EXPECT_EQ(solution.stats.leaves, direct.stats.leaves);
    write(dir.path() / "library.vtp", solution, scene);
    write_solution(dir.path() / "direct.vtp", direct, scene, kCreaseDegrees,
                   double(direct.stats.iterations.size()));
    EXPECT_EQ(read_file(dir.path() / "library.vtp"), read_file(dir.path() / "direct.vtp"));

    ReferenceOptions ro;
    ro.max_area = 0.01;
    ro.solver.rays = 100'000;
    const std::filesystem::path ref = dir.path() / "ref";
    OutputSet out(reference_files(ref, scene), ref);
    write_reference(out, ref, scene, compute_reference(scene, ro), ro, {});
    out.commit();
    const SolutionErrors measured = measure(solution, scene, ref);
    const SolutionErrors of_file =
        measure_solution(load_reference(ref, scene),
                         read_solution(dir.path() / "library.vtp", scene).mesh, scene, 2);
    EXPECT_GT(measured.object.relative_l2, 0);
    EXPECT_EQ(measured.object.relative_l2, of_file.object.relative_l2);
    EXPECT_EQ(measured.views.at("side").rmse_a, of_file.views.at("side").rmse_a);
}

}  // namespace
}  // namespace hmcr::test
