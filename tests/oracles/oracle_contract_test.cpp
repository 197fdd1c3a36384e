// SPDX-License-Identifier: Apache-2.0
// What every registered oracle promises, checked for each one automatically (a new oracle in
// the registry is tested without touching this file).
//
// The value of a link is w_ij times the oracle's geometric factor (oracle.h), so it scales
// linearly with w_ij by construction: the factor is never given w_ij. What is tested here is
// the factor: non-negative and finite on any kernel, zero on a uniform kernel (line-based
// oracles), and homogeneous in the kernel (scaling every F_k by c scales kl, mi, cs, hl, ks by
// c and vt by c^2, because the divergences depend only on p_k = F_k / F^).
#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "radiosity/oracle_registry.h"
#include "rays/rng.h"

namespace hmcr::test {
namespace {

class EveryRegisteredOracle : public testing::TestWithParam<const Oracle*> {};

LinkGeometry geometry(Rng& rng, std::vector<double>& kernel) {
    LinkGeometry g;
    g.receiver_area = std::pow(10.0, -4 * rng.uniform());
    g.source_area = std::pow(10.0, -4 * rng.uniform());
    g.total_area = 10;
    g.centre_distance = 0.01 + rng.uniform();
    g.receiver_cos = rng.uniform();
    g.source_cos = rng.uniform();
    for (double& f : kernel) f = rng.uniform() < 0.2 ? 0 : std::pow(10.0, 6 * rng.uniform() - 3);
    g.kernel = kernel;
    return g;
}

TEST_P(EveryRegisteredOracle, FactorIsNonNegativeAndFinite) {
    const Oracle& o = *GetParam();
    Rng rng(1, 0);
    std::vector<double> kernel(10);
    int positive = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const double v = o.geometric_factor(geometry(rng, kernel));
        ASSERT_TRUE(std::isfinite(v) && v >= 0) << o.name() << " trial " << trial << ": " << v;
        positive += v > 0;
    }
    EXPECT_GT(positive, 4000) << o.name();  // zero only for all-zero kernels (1e-7 of trials)
}

TEST_P(EveryRegisteredOracle, UniformKernelGivesZero) {
    const Oracle& o = *GetParam();
    if (!o.uses_lines()) GTEST_SKIP() << o.name() << " does not sample the kernel";
    Rng rng(2, 0);
    std::vector<double> kernel(10);
    for (int trial = 0; trial < 100; ++trial) {
        LinkGeometry g = geometry(rng, kernel);
        // The scale of the factor for this pair: the same kernel with one line doubled.
        std::fill(kernel.begin(), kernel.end(), kernel[0] + 1e-3);
        kernel[0] *= 2;
        const double scale = o.geometric_factor(g);
        ASSERT_GT(scale, 0) << trial;  // else the check below is 0 <= 0 for a dead oracle
        kernel[0] = kernel[1];
        EXPECT_LE(o.geometric_factor(g), 1e-12 * scale) << trial;
    }
}

TEST_P(EveryRegisteredOracle, FactorIsHomogeneousInTheKernel) {
    const Oracle& o = *GetParam();
    if (!o.uses_lines()) GTEST_SKIP() << o.name() << " does not sample the kernel";
    const double degree = o.name() == "vt" ? 2 : 1;
    Rng rng(3, 0);
    std::vector<double> kernel(10);
    for (int trial = 0; trial < 100; ++trial) {
        LinkGeometry g = geometry(rng, kernel);
        const double v = o.geometric_factor(g);
        ASSERT_GT(v, 0) << trial;  // a random kernel is not uniform: every oracle refines it
        for (double& f : kernel) f *= 7;
        EXPECT_NEAR(o.geometric_factor(g), std::pow(7.0, degree) * v, 1e-9 * v);
    }
}

TEST_P(EveryRegisteredOracle, HasANameADescriptionAndAPositiveDefaultEpsilon) {
    const Oracle& o = *GetParam();
    EXPECT_FALSE(o.name().empty());
    EXPECT_FALSE(o.description().empty());
    EXPECT_GT(o.default_epsilon(), 0);
    EXPECT_EQ(&find_named(oracle_registry(), o.name()), &o);
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryRegisteredOracle,
                         testing::ValuesIn(oracle_registry().all()),
                         [](const testing::TestParamInfo<const Oracle*>& p) {
                             return std::string(p.param->name());
                         });

}  // namespace
}  // namespace hmcr::test
