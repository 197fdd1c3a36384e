// SPDX-License-Identifier: Apache-2.0
#include "tests/support/furnace.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/statistics.h"

namespace hmcr::test {

std::size_t expect_furnace_per_patch(const PatchMesh& mesh, double rho, double e, int seeds,
                                     const std::function<SolverOptions(std::uint64_t)>& options,
                                     const std::function<void(const Solution&)>& check,
                                     const SolveInputs& inputs) {
    const std::size_t patches = mesh.n_faces();
    std::vector<std::vector<double>> per_patch(patches);
    std::size_t iterations = 0;
    for (std::uint64_t seed = 1; seed <= std::uint64_t(seeds); ++seed) {
        const Solution sol = solve(mesh, options(seed), inputs);
        if (check) check(sol);
        const std::size_t counted = sol.stats.value_iterations().size();
        // The expected value below assumes one K for every seed.
        if (seed > 1 && counted != iterations) {
            ADD_FAILURE() << "seed " << seed << ": " << counted << " iterations, not "
                          << iterations;
            return iterations;
        }
        iterations = counted;
        for (std::size_t p = 0; p < patches; ++p) {
            per_patch[p].push_back(sol.hierarchy->root(p).radiosity[1]);
        }
    }
    const double expected = furnace_value(rho, e, iterations);
    for (std::size_t p = 0; p < patches; ++p) {
        EXPECT_TRUE(
            t_test("furnace patch " + std::to_string(p), per_patch[p], expected, 0, int(patches)));
    }
    return iterations;
}

}  // namespace hmcr::test
