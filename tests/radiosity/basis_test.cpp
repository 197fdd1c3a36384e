// SPDX-License-Identifier: Apache-2.0
// Polynomial bases on elements (docs/design.md §3.14): orthonormal on the unit square and
// triangle, the constant first, spanning their monomials, and carried to children and back
// exactly. Nothing here is random but the test points: every expected value is exact, and the
// tolerances are a few hundred units in the last place of the sums' magnitudes (the cubic Gram
// matrix's condition number is below 10^5).
#include "radiosity/basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "rays/domain.h"
#include "rays/rng.h"

namespace hmcr::test {
namespace {

constexpr double kTolerance = 1e-11;

struct Case {
    Basis basis;
    bool quad;
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << basis_name(c.basis) << (c.quad ? " on the square" : " on the triangle");
}

std::string case_name(const testing::TestParamInfo<Case>& info) {
    return std::string(basis_name(info.param.basis)) + (info.param.quad ? "Square" : "Triangle");
}

class EveryBasis : public testing::TestWithParam<Case> {
protected:
    const PolynomialBasis& basis() const {
        return polynomial_basis(GetParam().basis, GetParam().quad);
    }
    // A point of the unit domain from the stream's next two uniforms.
    Vec2 point(Rng& rng) const {
        double a = rng.uniform(), b = rng.uniform();
        if (!GetParam().quad && a + b > 1) {
            a = 1 - a;
            b = 1 - b;
        }
        return {a, b};
    }
    PolynomialBasis::Coefficients random_coefficients(Rng& rng) const {
        PolynomialBasis::Coefficients c(basis().size());
        for (int k = 0; k < basis().size(); ++k) c[k] = 2 * rng.uniform() - 1;
        return c;
    }
};

TEST(DomainQuadrature, IntegratesMonomialsExactly) {
    for (const bool quad : {false, true}) {
        for (int i = 0; i <= 7; ++i) {
            for (int j = 0; j <= 7; ++j) {
                if (!quad && i + j > 6) continue;
                double sum = 0;
                for (const QuadraturePoint& q : domain_quadrature(quad))
                    sum += q.weight * std::pow(q.a, i) * std::pow(q.b, j);
                // Means over the unit square, and over the unit triangle of area 1/2.
                const double exact =
                    quad ? 1.0 / ((i + 1) * (j + 1))
                         : 2 * std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3);
                EXPECT_NEAR(sum, exact, 1e-15) << (quad ? "square " : "triangle ") << i << j;
            }
        }
    }
}

TEST(BasisSize, IsRenderParksForEveryApproximation) {
    EXPECT_EQ(basis_size(Basis::constant), 1);
    EXPECT_EQ(basis_size(Basis::linear), 3);
    EXPECT_EQ(basis_size(Basis::bilinear), 4);
    EXPECT_EQ(basis_size(Basis::quadratic), 6);
    EXPECT_EQ(basis_size(Basis::cubic), 10);
}

TEST_P(EveryBasis, IsOrthonormalInTheMeanOverTheDomain) {
    const PolynomialBasis& b = basis();
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(b.size(), b.size());
    for (const QuadraturePoint& q : domain_quadrature(b.quad())) {
        const auto psi = b.evaluate(q.a, q.b);
        gram += q.weight * psi * psi.transpose();
    }
    EXPECT_TRUE(gram.isApprox(Eigen::MatrixXd::Identity(b.size(), b.size()), kTolerance)) << gram;
}

TEST_P(EveryBasis, FirstFunctionIsOneSoTheFirstCoefficientIsTheMean) {
    Rng rng(1, 2, 3);
    for (int n = 0; n < 20; ++n) {
        const Vec2 p = point(rng);
        EXPECT_NEAR(basis().evaluate(p.x(), p.y())[0], 1.0, kTolerance);
    }
}

// The monomials a basis spans, as (exponent of a, exponent of b).
std::vector<std::pair<int, int>> spanned(Basis basis) {
    if (basis == Basis::bilinear) return {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    const int degree = basis == Basis::constant    ? 0
                       : basis == Basis::linear    ? 1
                       : basis == Basis::quadratic ? 2
                                                   : 3;
    std::vector<std::pair<int, int>> m;
    for (int d = 0; d <= degree; ++d) {
        for (int j = 0; j <= d; ++j) m.emplace_back(d - j, j);
    }
    return m;
}

// Every monomial the basis spans is its own projection: the coefficients by quadrature give it
// back at any point.
TEST_P(EveryBasis, SpansItsMonomials) {
    const PolynomialBasis& b = basis();
    const auto monomials = spanned(GetParam().basis);
    ASSERT_EQ(int(monomials.size()), b.size());
    Rng rng(1, 2, 4);
    for (const auto& [i, j] : monomials) {
        PolynomialBasis::Coefficients c = PolynomialBasis::Coefficients::Zero(b.size());
        for (const QuadraturePoint& q : domain_quadrature(b.quad()))
            c += q.weight * std::pow(q.a, i) * std::pow(q.b, j) * b.evaluate(q.a, q.b);
        for (int n = 0; n < 10; ++n) {
            const Vec2 p = point(rng);
            EXPECT_NEAR(b.value(c, p.x(), p.y()), std::pow(p.x(), i) * std::pow(p.y(), j),
                        kTolerance)
                << "a^" << i << " b^" << j;
        }
    }
}

// A function of the basis is the same function on each child in the child's basis: its value at
// a point of the child, in the child's local coordinates, equals the parent's at that point.
TEST_P(EveryBasis, CarriesAFunctionToEachChildExactly) {
    const PolynomialBasis& b = basis();
    Rng rng(1, 2, 5);
    const PolynomialBasis::Coefficients parent = random_coefficients(rng);
    const Domain root = Domain::root();
    for (int k = 0; k < 4; ++k) {
        const Domain child = root.child(b.quad(), k);
        const PolynomialBasis::Coefficients c = b.to_child(k, parent);
        for (int n = 0; n < 10; ++n) {
            const Vec2 p = point(rng);
            const double u = child.u0 + child.s * p.x(), v = child.v0 + child.s * p.y();
            EXPECT_NEAR(b.value(c, p.x(), p.y()), b.value(parent, u, v), kTolerance)
                << "child " << k;
        }
    }
}

TEST_P(EveryBasis, PullAfterPushIsTheIdentity) {
    const PolynomialBasis& b = basis();
    Rng rng(1, 2, 6);
    const PolynomialBasis::Coefficients parent = random_coefficients(rng);
    std::array<PolynomialBasis::Coefficients, 4> children;
    for (int k = 0; k < 4; ++k) children[std::size_t(k)] = b.to_child(k, parent);
    EXPECT_TRUE(b.from_children(children).isApprox(parent, kTolerance));
}

// The pull of four different children is their function's projection: its first coefficient is
// the children's mean, and its residual is orthogonal to every parent function (checked on the
// children's own quadrature points, exact for these products).
TEST_P(EveryBasis, PullIsTheProjectionOfThePiecewiseFunction) {
    const PolynomialBasis& b = basis();
    Rng rng(1, 2, 7);
    std::array<PolynomialBasis::Coefficients, 4> children;
    for (auto& c : children) c = random_coefficients(rng);
    const PolynomialBasis::Coefficients parent = b.from_children(children);
    EXPECT_NEAR(parent[0], (children[0][0] + children[1][0] + children[2][0] + children[3][0]) / 4,
                kTolerance);
    const Domain root = Domain::root();
    PolynomialBasis::Coefficients residual = PolynomialBasis::Coefficients::Zero(b.size());
    for (int k = 0; k < 4; ++k) {
        const Domain child = root.child(b.quad(), k);
        for (const QuadraturePoint& q : domain_quadrature(b.quad())) {
            const double u = child.u0 + child.s * q.a, v = child.v0 + child.s * q.b;
            const double difference =
                b.value(children[std::size_t(k)], q.a, q.b) - b.value(parent, u, v);
            residual += q.weight / 4 * difference * b.evaluate(u, v);
        }
    }
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), kTolerance) << residual.transpose();
}

INSTANTIATE_TEST_SUITE_P(Basis, EveryBasis,
                         testing::Values(Case{Basis::constant, true}, Case{Basis::constant, false},
                                         Case{Basis::linear, true}, Case{Basis::linear, false},
                                         Case{Basis::bilinear, true}, Case{Basis::bilinear, false},
                                         Case{Basis::quadratic, true},
                                         Case{Basis::quadratic, false}, Case{Basis::cubic, true},
                                         Case{Basis::cubic, false}),
                         case_name);

}  // namespace
}  // namespace hmcr::test
