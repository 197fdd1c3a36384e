// SPDX-License-Identifier: Apache-2.0
// The seven oracles against values computed by hand (docs/design.md §4.1): power from centre
// geometry, the six line-based ones for small kernel vectors with N_s = 4, A_i = 2, A_j = 3,
// A_T = 10; and the identities of section 4.2.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "common/error.h"
#include "radiosity/oracle_registry.h"
#include "rays/rng.h"

namespace hmcr::test {
namespace {

constexpr double kAi = 2, kAj = 3, kAt = 10;

double factor(const std::string& oracle, const std::vector<double>& kernel) {
    LinkGeometry g;
    g.receiver_area = kAi;
    g.source_area = kAj;
    g.total_area = kAt;
    g.kernel = kernel;
    return find_named(oracle_registry(), oracle).geometric_factor(g);
}

void expect_values(const std::vector<double>& kernel, const std::map<std::string, double>& want) {
    for (const auto& [name, value] : want) {
        EXPECT_NEAR(factor(name, kernel), value, 1e-12 * std::max(1.0, std::abs(value))) << name;
    }
}

// power = A_i f c_i c_j, f = A_j / (pi d^2 + A_j), c = max(cos theta, 2 f). With d^2 = 3 / pi,
// f = 3 / (3 + 3) = 1/2, so 2 f = 1 and c = 1 whatever the cosine: near elements always count.
// With d^2 = 27 / pi, f = 1/10, 2 f = 1/5: cos 0.6 is kept, a facing-away end (cos 0) gives
// 1/5, not 0 (the centre line says little about which parts of two elements see each other).
TEST(OracleFormulas, PowerFromCentreGeometry) {
    const auto power = [](double d2, double cos_i, double cos_j) {
        LinkGeometry g;
        g.receiver_area = kAi;
        g.source_area = kAj;
        g.total_area = kAt;
        g.centre_distance = std::sqrt(d2);
        g.receiver_cos = cos_i;
        g.source_cos = cos_j;
        return find_named(oracle_registry(), "power").geometric_factor(g);
    };
    const double pi = std::numbers::pi;
    EXPECT_NEAR(power(3 / pi, 0.1, 0.0), 2 * 0.5 * 1 * 1, 1e-12);
    EXPECT_NEAR(power(27 / pi, 0.6, 0.8), 2 * 0.1 * 0.6 * 0.8, 1e-12);
    EXPECT_NEAR(power(27 / pi, 0.6, 0.0), 2 * 0.1 * 0.6 * 0.2, 1e-12);
    EXPECT_NEAR(power(27 / pi, 0.0, 0.0), 2 * 0.1 * 0.2 * 0.2, 1e-12);
}

TEST(OracleFormulas, AllZeroKernelGivesZero) {
    expect_values({0, 0, 0, 0}, {{"ks", 0}, {"mi", 0}, {"kl", 0}, {"cs", 0}, {"hl", 0}, {"vt", 0}});
}

TEST(OracleFormulas, UniformKernelGivesZero) {
    expect_values({0.7, 0.7, 0.7, 0.7},
                  {{"ks", 0}, {"mi", 0}, {"kl", 0}, {"cs", 0}, {"hl", 0}, {"vt", 0}});
}

// F = (0, 0, 0, 2): F^ = 2, F_avg = 0.5, p = (0, 0, 0, 1), the most concentrated kernel.
TEST(OracleFormulas, SingleNonZeroLine) {
    const double ln2 = std::log(2.0);
    expect_values({0, 0, 0, 2},
                  {
                      {"ks", 3 * 1.5},           // A_j max(2 - 0.5, 0.5 - 0)
                      {"mi", 0.6 * ln2},         // (6/10) [(2 ln 2)/4 - 0.5 ln 0.5]
                      {"kl", 12 * 2 * ln2},      // A_i A_j F^ = 12, D = ln 4 (its maximum)
                      {"cs", 12 * 3.0},          // chi2 = 4 (3/16 + 9/16) = 3 = N_s - 1
                      {"hl", 12 * 0.5},          // h2 = (3/4 + 1/4) / 2
                      {"vt", 6 * 4 * 3.0 / 16},  // A_i A_j F^2 V, V = 1/4 - 1/16
                  });
}

// F = (1, 2, 3, 10): F^ = 16, F_avg = 4, p = (1, 2, 3, 10) / 16.
TEST(OracleFormulas, SpikyKernel) {
    using std::log, std::sqrt;
    const double d = log(0.25) / 16 + log(0.5) / 8 + 3 * log(0.75) / 16 + 10 * log(2.5) / 16;
    const double gap = (2 * log(2.0) + 3 * log(3.0) + 10 * log(10.0)) / 4 - 4 * log(4.0);
    const double h2 =
        0.5 * (std::pow(sqrt(1.0 / 16) - 0.5, 2) + std::pow(sqrt(2.0 / 16) - 0.5, 2) +
               std::pow(sqrt(3.0 / 16) - 0.5, 2) + std::pow(sqrt(10.0 / 16) - 0.5, 2));
    expect_values({1, 2, 3, 10}, {
                                     {"ks", 3 * 6.0},               // A_j max(10 - 4, 4 - 1)
                                     {"mi", 0.6 * gap},             // Jensen's gap of x ln x
                                     {"kl", 6 * 16 * d},            // d = 0.34545...
                                     {"cs", 6 * 16 * 200 / 256.0},  // chi2 = 4 * 50 / 256
                                     {"hl", 6 * 16 * h2},
                                     {"vt", 6 * 256 * 50 / 1024.0},  // V = 114/1024 - 1/16
                                 });
}

std::vector<double> random_kernel(Rng& rng, int n) {
    std::vector<double> f(std::size_t(n), 0.0);
    for (double& x : f) {
        const double u = rng.uniform();
        x = u < 0.3 ? 0.0 : std::pow(10.0, 4 * rng.uniform() - 2);  // zeros and 4 decades
    }
    return f;
}

// docs/design.md §4.2: mi = kl / (A_T N_s) on the same lines; D <= ln N_s, chi2 <= N_s - 1, h2 <=
// 1, V >= 0, and the mi bracket (Jensen's gap) >= 0.
TEST(OracleIdentities, HoldOnRandomKernels) {
    Rng rng(42, 0);
    for (int trial = 0; trial < 2000; ++trial) {
        const int n = 2 + int(rng.uniform() * 30);
        const auto f = random_kernel(rng, n);
        double sum = 0;
        for (double x : f) sum += x;
        const double kl = factor("kl", f), mi = factor("mi", f);
        EXPECT_NEAR(mi, kl / (kAt * n), 1e-12 * kl) << trial;
        if (sum == 0) continue;
        const double pair = kAi * kAj * sum;
        EXPECT_LE(kl / pair, std::log(double(n)) * (1 + 1e-12));
        EXPECT_LE(factor("cs", f) / pair, (n - 1) * (1 + 1e-12));
        EXPECT_LE(factor("hl", f) / pair, 1.0);
        EXPECT_GE(factor("vt", f), 0.0);
        EXPECT_GE(mi, 0.0);
    }
}

}  // namespace
}  // namespace hmcr::test
