// SPDX-License-Identifier: Apache-2.0
#include "tests/support/energy_balance.h"

#include <gtest/gtest.h>

namespace hmcr::test {

void expect_energy_balance(const Solution& sol, bool shoots_its_unshot) {
    const Hierarchy& h = *sol.hierarchy;
    Rgb absorbed = Rgb::Zero();
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        const Patch& patch = h.patch_set().patches[p];
        const Rgb& rho = h.patch_set().reflectance(patch);
        const Rgb irradiance = (h.root(p).radiosity - h.patch_set().emission(patch)) / rho;
        absorbed += patch.area * (1 - rho) * irradiance;
    }
    Rgb reflected = Rgb::Zero();
    for (const IterationRecord& it : sol.stats.value_iterations()) reflected += it.unshot_after;
    const SolveStats& st = sol.stats;
    const Rgb out = absorbed + reflected + st.escaped_power + st.back_face_power;
    EXPECT_TRUE(out.isApprox(st.shot_power, 1e-9))
        << out.transpose() << " vs " << st.shot_power.transpose();
    if (!shoots_its_unshot) return;
    const double balance =
        (absorbed + st.escaped_power + st.back_face_power + st.unshot_power).sum();
    EXPECT_NEAR(balance, st.emitted_power.sum(), 1e-9 * st.emitted_power.sum());
}

}  // namespace hmcr::test
