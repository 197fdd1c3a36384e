// SPDX-License-Identifier: Apache-2.0
// Hostile MGF under mpirun: every rank reads the scene, and the refusal is said once, by rank 0,
// with exit code 2 (slow: mpirun takes seconds to start).
#include <string>

#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

// 20,000 nested transformations once overflowed every rank's stack.
TEST_F(Hostile, DeepNestingUnderMpirunIsRefusedOnce) {
    std::string text = "m lamp =\ned 100\nv c =\np 0 0 0\n";
    for (int i = 0; i < 20000; ++i) text += "xf -t 0 0 0\n";
    text += "sph c 1\n";
    for (int i = 0; i < 20000; ++i) text += "xf\n";
    m_temp.write("deep.mgf", text);
    const auto before = snapshot(dir());
    const CliRun r = run_hmcr_mpi(2, "solve deep.mgf -o out.vtp", dir());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    const std::string error = "hmcr: error: deep.mgf:1005: transformations and includes nested";
    const std::size_t first = r.err.find(error);
    EXPECT_NE(first, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("hmcr: error:", first + 1), std::string::npos) << r.err;
    EXPECT_TRUE(snapshot(dir()) == before);
}

}  // namespace
}  // namespace hmcr::test
