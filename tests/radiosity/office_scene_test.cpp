// SPDX-License-Identifier: Apache-2.0
// The generated office (scenes/office/generate.py) on a small instance: the face count its
// plan gives, no repairs, and closed: no ray leaves it but by round-off.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "meshes/scene.h"
#include "radiosity/oracle_registry.h"
#include "radiosity/solver.h"
#include "tests/support/temp_dir.h"

namespace hmcr::test {
namespace {

TEST(OfficeScene, ASmallInstanceHasItsPlannedFacesAndIsClosed) {
    TempDir dir;
    const std::string script = (scene_directory() / "office" / "generate.py").string();
    const std::string command = "python3 '" + script +
                                "' --bays 2 --tile 0.4 --name office2 --out '" +
                                dir.path().string() + "' > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    LoadOptions one_sided;  // as office.json says: its lights' backs face the void above
    one_sided.sides = 1;
    const Scene scene = load_scene((dir.path() / "office2.obj").string(), one_sided);
    // 2 x 2 bays of 8 x 8 tiles: floor and ceiling 16 x 16 each, four walls 16 x 8, and per
    // bay a desk (slab 6 + 4 legs x 4), a chair (seat 6 + 4 legs x 4 + back 5), a cabinet (5).
    EXPECT_EQ(scene.mesh.n_faces(), 2u * 16 * 16 + 4u * 16 * 8 + 4u * (22 + 27 + 5));
    EXPECT_TRUE(scene.repairs.empty()) << scene.repairs.summary();
    SolverOptions o;
    o.oracle = oracle_registry().find("power");
    o.rays = 200'000;
    const Solution sol = solve(scene.mesh, o);
    // Closed: what escapes is float round-off at shared edges (cube-room: 1.3e-5 of the shot
    // power); one missing 0.4 m tile would let out about 1e-3.
    EXPECT_LT(channel_sum(sol.stats.escaped_power) / channel_sum(sol.stats.shot_power), 1e-4);
    // Only the floor under the legs and cabinets is hidden (rays from it hit a back face).
    EXPECT_LT(sol.stats.back_face_fraction(), 0.02);
}

}  // namespace
}  // namespace hmcr::test
