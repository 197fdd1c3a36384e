// SPDX-License-Identifier: Apache-2.0
// The pixel sampling criteria against values computed by hand: equal samples never refine, an
// outlier does, by the amount each formula gives; and the contract every registered criterion
// keeps (run over the registry, so a new criterion is tested by adding it).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "common/error.h"
#include "rays/rng.h"
#include "trace/criteria/display_values.h"
#include "trace/criteria/registry.h"

namespace hmcr::test {
namespace {

// Grey samples (r = g = b, so luminance = the value) at one geometric factor.
std::vector<PixelSample> grey(const std::vector<double>& values, double geometry = 1) {
    std::vector<PixelSample> s;
    for (double v : values) s.push_back({Rgb::Constant(v), geometry});
    return s;
}

double value(const std::string& name, const std::vector<PixelSample>& s, double area = 1) {
    return find_named(criterion_registry(), name).value(s, area);
}

// On display values an outlier that is white on the screen anyway does not refine: 1 x 7 and 9
// at exposure 1 clamp to eight 1s. At exposure 0.1 nothing clamps, and the value is the
// criterion's of the scaled samples (kl is linear in the scale through L-bar).
TEST(Criteria, DisplayValuesClampAtWhite) {
    const auto s = grey({1, 1, 1, 1, 1, 1, 1, 9});
    for (const char* name : {"cc", "var", "kl", "srhe", "entropy"}) {
        EXPECT_EQ(on_display_values(find_named(criterion_registry(), name), 1.0)->value(s, 1), 0)
            << name;
        EXPECT_GT(on_display_values(find_named(criterion_registry(), name), 0.1)->value(s, 1), 0)
            << name;
    }
    EXPECT_NEAR(on_display_values(find_named(criterion_registry(), "kl"), 0.1)->value(s, 1),
                0.1 * value("kl", s), 1e-15);
}

// Eight luminances 1, ..., 1, 9: n = 8, sum 16, L-bar = 2, p = (1/16 x 7, 9/16).
TEST(Criteria, OneOutlierAmongEightByHand) {
    const auto s = grey({1, 1, 1, 1, 1, 1, 1, 9});
    const double d = 7.0 / 16 * std::log(0.5) + 9.0 / 16 * std::log(4.5);
    const double chi2 = 8 * (7 * (1.0 / 256) + 49.0 / 256);  // 1.75
    const double r8 = std::sqrt(1.0 / 8);
    const double h2 = 0.5 * (7 * (0.25 - r8) * (0.25 - r8) + (0.75 - r8) * (0.75 - r8));
    const std::map<std::string, double> want = {
        {"kl", 2 * d / 8},
        {"cs", 2 * chi2 / 8},
        {"he", 2 * h2 / 8},
        {"srkl", 2 * std::sqrt(d) / 8},
        {"srcs", 2 * std::sqrt(chi2) / 8},
        {"srhe", 2 * std::sqrt(h2) / 8},
        {"cc", 2 * 8.0 / 10},
    };
    for (const auto& [name, v] : want) EXPECT_NEAR(value(name, s), v, 1e-12 * v) << name;
    // var: s^2 = 56 / 7 = 8, s / sqrt(n) = 1, so the value is t(0.95, 7) = 1.894579 (tables),
    // which the criterion's expansion gives within 2e-5.
    EXPECT_NEAR(value("var", s), 1.894579, 2e-5 * 1.894579);
}

// Four node samples 1, 1, 1, 9 at one geometric factor, a depth-1 node (area 1/4): c-bar = 3,
// q = 3/4 in every channel; entropy: p = (1, 1, 1, 9) / 12, D = ln(3) / 2, C = D / ln 4;
// binary: p = (0.9, 0.1), C = D / ln 2. Equal geometry: C^g = 0, so value = delta C q.
TEST(Criteria, EntropyContrastOfANodeByHand) {
    const auto s = grey({1, 1, 1, 9});
    const double entropy = 0.5 * std::log(3.0) / std::log(4.0);
    const double binary = (0.9 * std::log(1.8) + 0.1 * std::log(0.2)) / std::numbers::ln2;
    EXPECT_NEAR(value("entropy", s, 0.25), 0.9 * 0.75 * entropy, 1e-12);
    EXPECT_NEAR(value("binary-entropy", s, 0.25), 0.9 * 0.75 * binary, 1e-12);
    // Importance q = c-bar / 4^level: the same samples on the whole pixel weigh 4 times more.
    EXPECT_NEAR(value("entropy", s, 1), 4 * value("entropy", s, 0.25), 1e-12);
}

// Equal colours 2 and geometric factors (1, 1, 1, 5): only the geometric term, weighed by the
// colour importance q-bar = 2 area: value = (1 - delta) C^g q-bar.
TEST(Criteria, EntropyGeometricContrastByHand) {
    std::vector<PixelSample> s = grey({2, 2, 2, 2});
    s[3].geometry = 5;
    const double d = 3.0 / 8 * std::log(0.5) + 5.0 / 8 * std::log(2.5);
    EXPECT_NEAR(value("entropy", s, 1), 0.1 * d / std::log(4.0) * 2, 1e-12);
    const double binary =
        (5.0 / 6 * std::log(5.0 / 3) + 1.0 / 6 * std::log(1.0 / 3)) / std::numbers::ln2;
    EXPECT_NEAR(value("binary-entropy", s, 1), 0.1 * binary * 2, 1e-12);
}

class EveryCriterion : public testing::TestWithParam<const Criterion*> {
protected:
    std::size_t n() const { return GetParam()->scheme() == Scheme::quadtree ? 4 : 8; }
};

TEST_P(EveryCriterion, EqualSamplesNeverRefine) {
    for (const double v : {0.0, 0.3, 7.0}) {
        const auto s = grey(std::vector<double>(n(), v), 0.5);
        EXPECT_EQ(GetParam()->value(s, 1), 0) << v;
        EXPECT_LE(GetParam()->value(s, 1), 1e-300) << "refines at any positive threshold";
    }
}

TEST_P(EveryCriterion, OneOutlierRefines) {
    if (GetParam()->scheme() == Scheme::uniform) GTEST_SKIP() << "uniform is never asked";
    std::vector<double> v(n(), 0.2);
    v[1] = 3;
    EXPECT_GT(GetParam()->value(grey(v), 1), 0);
}

TEST_P(EveryCriterion, ValuesAreFiniteAndNotNegative) {
    Rng rng(3, 4);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<PixelSample> s(n() * std::size_t(1 + trial % 3));
        for (PixelSample& x : s) {
            // Zeros (misses, black walls) among the values, like real pixels.
            for (int c = 0; c < 3; ++c) x.radiance[c] = rng.uniform() < 0.2 ? 0 : rng.uniform();
            x.geometry = rng.uniform() < 0.1 ? 0 : 10 * rng.uniform();
        }
        const double v = GetParam()->value(s, 0.25);
        EXPECT_TRUE(std::isfinite(v) && v >= 0) << v;
    }
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryCriterion, testing::ValuesIn(criterion_registry().all()),
                         [](const auto& p) {
                             std::string name(p.param->name());
                             for (char& c : name) c = c == '-' ? '_' : c;
                             return name;
                         });

TEST(Criteria, UnknownNameListsTheValidOnes) {
    try {
        find_named(criterion_registry(), "nope");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "unknown sampler 'nope' (valid: uniform, cc, var, entropy, "
                     "binary-entropy, kl, cs, he, srkl, srcs, srhe, half-difference)");
    }
}

}  // namespace
}  // namespace hmcr::test
